# Writes JPEG, TGA and TIFF variants with independent writers (Pillow, ImageMagick) and an
# independent decoding of each as the reference, for tests/core/ImageConformanceTest.cpp (which
# writes the EXR variants itself, with OpenEXR's own library). Usage: image_conformance.py DIR.
# For each variant it writes NAME.EXT and NAME.f32 (float32 texels, row by row, as many channels
# as OpenImageIO presents: palettes expand to RGB, CMYK JPEGs convert to RGB), and prints one line
# "NAME.EXT WIDTH HEIGHT CHANNELS TOLERANCE" per variant; TOLERANCE is the largest difference
# allowed per sample, 0 where both sides divide the same integers.
import array
import subprocess
import sys

from PIL import Image

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from conformance_pattern import H, W, pattern, rgba  # noqa: E402 (after the line above)

out = sys.argv[1]


def smooth(x, y):
    # JPEG's reference decoders agree to the bit only where every decoder does the same work;
    # gradients keep the DCT's rounding small so the tolerance below means something.
    return (x * 3 + y * 4) % 256


def rgb(f=pattern):
    im = Image.new("RGB", (W, H))
    im.putdata([(f(x, y), f(y, x), (x * 4 + y) % 256) for y in range(H) for x in range(W)])
    return im


def grey(f=pattern):
    im = Image.new("L", (W, H))
    im.putdata([f(x, y) for y in range(H) for x in range(W)])
    return im


def palette(colours):
    im = Image.new("P", (W, H))
    im.putpalette([c for i in range(colours) for c in ((i * 53) % 256, (i * 97) % 256, 255 - i)])
    im.putdata([(x + 3 * y) % colours for y in range(H) for x in range(W)])
    return im


def write_floats(name, values):
    with open(f"{out}/{name}.f32", "wb") as f:
        array.array("f", values).tofile(f)


def pillow_reference(name, path, channels, tolerance):
    im = Image.open(path)
    im.load()
    if im.mode == "F":
        values = list(im.getdata())
    elif im.mode in ("I;16", "I;16B", "I;16L", "I"):
        values = [v / 65535.0 for v in im.getdata()]
    elif channels == 1:
        values = [v / 255.0 for v in im.convert("L").getdata()]
    else:
        mode = {2: "LA", 3: "RGB", 4: "RGBA"}[channels]
        values = [c / 255.0 for px in im.convert(mode).getdata() for c in px]
    write_floats(name, values)
    print(path.rsplit("/", 1)[1], im.size[0], im.size[1], channels, tolerance)


def magick_reference(name, path, channels):
    # ImageMagick's own decoding, as 16-bit samples: for files Pillow reads only at 8 bits.
    layout = {1: "gray", 3: "rgb", 4: "rgba"}[channels]
    raw = subprocess.run(["convert", path, "-depth", "16", "-endian", "LSB", f"{layout}:-"],
                         check=True, capture_output=True).stdout
    samples = array.array("H")
    samples.frombytes(raw)
    write_floats(name, [v / 65535.0 for v in samples])
    print(path.rsplit("/", 1)[1], W, H, channels, 0)


def save(name, extension, im, channels, tolerance=0, **options):
    path = f"{out}/{name}.{extension}"
    im.save(path, **options)
    pillow_reference(name, path, channels, tolerance)


def magick(name, extension, source, channels, *arguments, reference="pillow", tolerance=0):
    path = f"{out}/{name}.{extension}"
    subprocess.run(["convert", source, *arguments, path], check=True)
    if reference == "magick":
        magick_reference(name, path, channels)
    else:
        pillow_reference(name, path, channels, tolerance)


# JPEG. OpenImageIO and Pillow both decode with libjpeg-turbo's defaults (islow IDCT, fancy
# upsampling), so they agree to the bit; one level in 255 leaves room for another build's SIMD.
one = 1.0 / 255.0 + 1e-6
save("jpeg-grey", "jpg", grey(smooth), 1, one, quality=92)
save("jpeg-baseline-420", "jpg", rgb(smooth), 3, one, quality=90)
save("jpeg-baseline-444", "jpg", rgb(smooth), 3, one, quality=95, subsampling=0)
save("jpeg-progressive", "jpg", rgb(smooth), 3, one, quality=90, progressive=True)
save("jpeg-optimized", "jpg", rgb(smooth), 3, one, quality=85, optimize=True)
# CMYK as Photoshop saves it (Adobe APP14 marker, inverted samples); both sides convert to RGB as
# (255 - C) (255 - K) / 255.
cmyk = Image.new("CMYK", (W, H))
cmyk.putdata([(smooth(x, y), smooth(y, x), (x * 4) % 256, (y * 3) % 128)
              for y in range(H) for x in range(W)])
save("jpeg-cmyk", "jpg", cmyk, 3, one, quality=95)
magick("jpeg-magick-progressive", "jpg", f"{out}/jpeg-baseline-444.jpg", 3, "-interlace",
       "JPEG", "-quality", "90", tolerance=one)
# TGA: uncompressed and run-length, top-down and bottom-up, grey, RGB(A) and colour-mapped.
save("tga-rgb", "tga", rgb(), 3)
save("tga-rgba", "tga", rgba(), 4)
save("tga-rgb-rle", "tga", rgb(), 3, compression="tga_rle")
save("tga-rgba-rle", "tga", rgba(), 4, compression="tga_rle")
save("tga-grey", "tga", grey(), 1)
save("tga-grey-rle", "tga", grey(), 1, compression="tga_rle")
save("tga-palette", "tga", palette(200), 3)
save("tga-palette-rle", "tga", palette(16), 3, compression="tga_rle")
save("tga-top-down", "tga", rgb(), 3, orientation=1)
magick("tga-magick-rle", "tga", f"{out}/tga-rgb.tga", 3, "-compress", "RLE")
magick("tga-magick-palette", "tga", f"{out}/tga-palette.tga", 3, "-type", "Palette")

# TIFF: strips (uncompressed, LZW, deflate, PackBits), tiles, 1/8/16-bit grey, 16-bit RGB,
# 32-bit float, palette, planar configuration 2 (a plane per channel).
save("tiff-rgb", "tif", rgb(), 3)
save("tiff-rgb-lzw", "tif", rgb(), 3, compression="tiff_lzw")
save("tiff-rgba-deflate", "tif", rgba(), 4, compression="tiff_adobe_deflate")
save("tiff-rgb-packbits", "tif", rgb(), 3, compression="packbits")
# Bilevel: Pillow leaves out the BitsPerSample tag (1 by the TIFF specification's default),
# which OpenImageIO 2.4 reads as 8 bits: Relief refuses that file with a message naming the tag
# (printed as "NAME.EXT refused WHAT"); ImageMagick writes the tag, and that file is read.
bilevel = f"{out}/tiff-grey1-untagged.tif"
grey().point(lambda v: 255 if v > 127 else 0).convert("1").save(bilevel)
print("tiff-grey1-untagged.tif refused BitsPerSample")
magick("tiff-grey1", "tif", bilevel, 1, "-monochrome")
save("tiff-grey8", "tif", grey(), 1)
grey16 = Image.new("I;16", (W, H))
grey16.putdata([pattern(x, y) * 257 + x for y in range(H) for x in range(W)])
save("tiff-grey16", "tif", grey16, 1)
floats = Image.new("F", (W, H))
# Height maps from sculpting tools: negative and above one, kept as stored.
floats.putdata([(pattern(x, y) - 64) / 37.0 for y in range(H) for x in range(W)])
save("tiff-float", "tif", floats, 1)
# TIFF palettes hold 16-bit entries; Pillow stores v << 8, which libtiff (and Pillow) read back
# as v >> 8, while OpenImageIO 2.4 scales by 255 / 65535 and truncates: v - 1 for every v > 0.
save("tiff-palette", "tif", palette(200), 3, one)
magick("tiff-tiled", "tif", f"{out}/tiff-rgb.tif", 3, "-define", "tiff:tile-geometry=16x16")
magick("tiff-tiled-lzw", "tif", f"{out}/tiff-grey8.tif", 1, "-define",
       "tiff:tile-geometry=32x16", "-compress", "LZW")
magick("tiff-rgb16", "tif", f"{out}/tiff-rgb.tif", 3, "-depth", "16", "-evaluate", "multiply",
       "0.999", reference="magick")
magick("tiff-rgb16-tiled", "tif", f"{out}/tiff-rgb.tif", 3, "-depth", "16", "-evaluate",
       "multiply", "0.997", "-define", "tiff:tile-geometry=16x16", reference="magick")
magick("tiff-planar", "tif", f"{out}/tiff-rgb.tif", 3, "-interlace", "Plane")
# Two pages (a scanner's or a layered export's): the first is read.
pages = f"{out}/tiff-pages.tif"
rgb().save(pages, save_all=True, append_images=[grey()])
pillow_reference("tiff-pages", pages, 3, 0)
