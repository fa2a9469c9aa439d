# Writes PNG variants with independent writers (Pillow, ImageMagick) and Pillow's decoding of
# each as the reference, for tests/core/PngConformanceTest.cpp. Usage: png_conformance.py DIR.
# For each NAME it writes NAME.png and NAME.f32 (float32 texels, row by row, values in [0, 1],
# as many channels as OpenImageIO presents: palette images expand to RGB, or RGBA with tRNS),
# and prints one line "NAME WIDTH HEIGHT CHANNELS" per variant.
import subprocess
import zlib
import sys

from PIL import Image, ImageCms, PngImagePlugin

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from conformance_pattern import H, W, pattern, rgba  # noqa: E402 (after the line above)

out = sys.argv[1]


def grey(levels):
    im = Image.new("L", (W, H))
    im.putdata([pattern(x, y) * (levels - 1) // 255 * (255 // (levels - 1))
                for y in range(H) for x in range(W)])
    return im


def palette(colours):
    im = Image.new("P", (W, H))
    im.putpalette([c for i in range(colours) for c in ((i * 53) % 256, (i * 97) % 256, 255 - i)])
    im.putdata([(x + 3 * y) % colours for y in range(H) for x in range(W)])
    return im


def reference(name, path, channels):
    im = Image.open(path)
    im.load()
    if channels == 1:
        if im.mode in ("I", "I;16", "I;16B"):
            values = [v / 65535.0 for v in im.getdata()]
        else:
            values = [v / 255.0 for v in im.convert("L").getdata()]
    else:
        mode = {2: "LA", 3: "RGB", 4: "RGBA"}[channels]
        values = [c / 255.0 for px in im.convert(mode).getdata() for c in px]
    import array
    array.array("f", values).tofile(open(f"{out}/{name}.f32", "wb"))
    print(name, im.size[0], im.size[1], channels)


def save(name, im, channels, **options):
    path = f"{out}/{name}.png"
    im.save(path, **options)
    reference(name, path, channels)


def magick(name, source, channels, *arguments):
    path = f"{out}/{name}.png"
    subprocess.run(["convert", source, *arguments, path], check=True)
    reference(name, path, channels)


save("grey1", grey(2).convert("1"), 1)
save("grey8", grey(256), 1)
i16 = Image.new("I;16", (W, H))
i16.putdata([pattern(x, y) * 257 + x for y in range(H) for x in range(W)])
save("grey16", i16, 1)
save("greyalpha8", rgba().convert("LA"), 2)
save("rgb8", rgba().convert("RGB"), 3)
save("rgba8", rgba(), 4)
for bits, colours in ((1, 2), (2, 4), (4, 16), (8, 200)):
    save(f"palette{bits}", palette(colours), 3, bits=bits)
# A game height map as image editors save them: 512x512, four grey levels in flat terraces, a
# palette, a few hundred bytes (its RGB expansion is more than deflate's 1:1032 of the file).
terraces = Image.new("P", (512, 512))
terraces.putpalette([v for i in range(4) for v in (i * 85,) * 3])
terraces.putdata([y // 128 for y in range(512) for x in range(512)])
save("palette-512-terraces", terraces, 3, optimize=True)
# tRNS for a palette: one alpha per entry (Pillow writes it from the "transparency" list).
save("palette8-trns", palette(200), 4, transparency=bytes((i * 5) % 256 for i in range(200)))
save("palette4-trns", palette(16), 4, bits=4, transparency=bytes(i * 16 for i in range(16)))
for bits in (2, 4):
    source = f"{out}/source-grey{bits}.png"
    grey(1 << bits).save(source)
    magick(f"grey{bits}", source, 1, "-depth", str(bits))
magick("grey8-adam7", f"{out}/grey8.png", 1, "-interlace", "PNG")
magick("rgba8-adam7", f"{out}/rgba8.png", 4, "-interlace", "PNG")
magick("palette8-adam7", f"{out}/palette8.png", 3, "-interlace", "PNG", "-define",
       "png:color-type=3")
# Colour chunks change no stored value: gAMA, sRGB and an ICC profile (iCCP) are read past.
chunks = PngImagePlugin.PngInfo()
chunks.add(b"gAMA", (45455).to_bytes(4, "big"))
save("rgb8-gama", rgba().convert("RGB"), 3, pnginfo=chunks)
chunks = PngImagePlugin.PngInfo()
chunks.add(b"sRGB", b"\x00")
save("rgb8-srgb", rgba().convert("RGB"), 3, pnginfo=chunks)
profile = ImageCms.ImageCmsProfile(ImageCms.createProfile("sRGB")).tobytes()
save("rgb8-iccp", rgba().convert("RGB"), 3, icc_profile=profile)
# The chunks that make a map linear data: a gAMA of 1.0, or OpenImageIO's "oiio:ColorSpace"
# text in a tEXt, zTXt (compressed) or iTXt chunk (tests/core/PngConformanceTest.cpp compares
# the colour space Relief reads with OpenImageIO's reading of the same file).
chunks = PngImagePlugin.PngInfo()
chunks.add(b"gAMA", (100000).to_bytes(4, "big"))
save("grey8-gama1", grey(256), 1, pnginfo=chunks)
chunks = PngImagePlugin.PngInfo()
chunks.add(b"gAMA", (99800).to_bytes(4, "big"))
save("grey8-gama-near1", grey(256), 1, pnginfo=chunks)
chunks = PngImagePlugin.PngInfo()
chunks.add_text("oiio:ColorSpace", "Linear")
save("grey8-text-linear", grey(256), 1, pnginfo=chunks)
chunks = PngImagePlugin.PngInfo()
chunks.add_text("oiio:ColorSpace", "Linear", zip=True)
save("grey8-ztxt-linear", grey(256), 1, pnginfo=chunks)
chunks = PngImagePlugin.PngInfo()
chunks.add_itxt("oiio:ColorSpace", "linear", lang="en", tkey="", zip=False)
save("grey8-itxt-linear", grey(256), 1, pnginfo=chunks)
chunks = PngImagePlugin.PngInfo()
chunks.add(b"gAMA", (100000).to_bytes(4, "big"))
chunks.add_text("oiio:ColorSpace", "sRGB")
save("grey8-gama1-text-srgb", grey(256), 1, pnginfo=chunks)


# Damaged files, each to be refused with a message: printed as "NAME broken WHAT".
def chunk(kind, data):
    body = kind + data
    return len(data).to_bytes(4, "big") + body + zlib.crc32(body).to_bytes(4, "big")


def broken(name, what, data):
    open(f"{out}/{name}.png", "wb").write(data)
    print(name, "broken", what)


good = open(f"{out}/rgb8.png", "rb").read()
idat = good.index(b"IDAT")
flipped = bytearray(good)
flipped[idat + 10] ^= 0x20
broken("broken-crc", "CRC", bytes(flipped))
broken("broken-truncated", "truncated", good[: idat + 30])
# A palette of two entries whose pixels use index 3.
rows = b"".join(b"\x00" + bytes([0b11100100] * 4) for _ in range(4))
broken("broken-index", "palette index",
       b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", (16).to_bytes(4, "big") + (4).to_bytes(4, "big") +
                                    bytes([2, 3, 0, 0, 0])) +
       chunk(b"PLTE", bytes([0, 0, 0, 255, 255, 255])) + chunk(b"IDAT", zlib.compress(rows)) +
       chunk(b"IEND", b""))
