# The test picture both conformance scripts (png_conformance.py, image_conformance.py) write in
# every format: odd sizes, so no row, byte of packed samples, or tile ends on a boundary of 8 or
# 16, and texels that differ from their neighbours in every channel.
from PIL import Image

W, H = 61, 37


def pattern(x, y):
    return (x * 7 + y * 13 + (x * y) % 11) % 256


def rgba():
    im = Image.new("RGBA", (W, H))
    im.putdata([(pattern(x, y), pattern(y, x), (x * 4) % 256, (y * 7 + 40) % 256)
                for y in range(H) for x in range(W)])
    return im
