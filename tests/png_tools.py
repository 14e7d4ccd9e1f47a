"""PNGs read in the test scripts, through Pillow (python3-pil, installed by scripts/setup).

tests/cli.sh puts this folder on PYTHONPATH, so a case's python says `from png_tools import load`.
"""
from PIL import Image


def load(path):
    """Returns (width, height, rows) with rows[y] a bytearray of RGBA, top row first."""
    with Image.open(path) as image:
        rgba = image.convert("RGBA")
        w, h = rgba.size
        data = rgba.tobytes()
    stride = w * 4
    return w, h, [bytearray(data[y * stride:(y + 1) * stride]) for y in range(h)]


def size(path):
    """(width, height) from the header alone."""
    with Image.open(path) as image:
        return image.size


def differing(a, b, x0, y0, x1, y1, step=2, tol=24):
    """Share of sampled pixels in the rectangle whose colours differ by more than tol (sum of RGB)."""
    n = d = 0
    for y in range(y0, y1, step):
        for x in range(x0, x1, step):
            n += 1
            d += sum(abs(a[y][4 * x + c] - b[y][4 * x + c]) for c in range(3)) > tol
    return d / max(n, 1)
