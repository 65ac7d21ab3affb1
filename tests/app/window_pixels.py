#!/usr/bin/env python3
"""Reads a window's pixels back from the X server (XGetImage through libX11, standard library only)
and writes them as a binary PPM: window_pixels.py WINDOW_ID OUT.ppm. For the window tests under Xvfb
(24-bit TrueColor: 32 bits a pixel, blue in the low byte)."""
import ctypes
import ctypes.util
import sys


class XWindowAttributes(ctypes.Structure):
    _fields_ = [("x", ctypes.c_int), ("y", ctypes.c_int), ("width", ctypes.c_int), ("height", ctypes.c_int),
                ("rest", ctypes.c_byte * 256)]


class XImage(ctypes.Structure):
    _fields_ = [("width", ctypes.c_int), ("height", ctypes.c_int), ("xoffset", ctypes.c_int),
                ("format", ctypes.c_int), ("data", ctypes.POINTER(ctypes.c_ubyte)), ("byte_order", ctypes.c_int),
                ("bitmap_unit", ctypes.c_int), ("bitmap_bit_order", ctypes.c_int), ("bitmap_pad", ctypes.c_int),
                ("depth", ctypes.c_int), ("bytes_per_line", ctypes.c_int), ("bits_per_pixel", ctypes.c_int)]


def main():
    window, out = int(sys.argv[1], 0), sys.argv[2]
    x11 = ctypes.CDLL(ctypes.util.find_library("X11"))
    x11.XOpenDisplay.restype = ctypes.c_void_p
    x11.XGetImage.restype = ctypes.POINTER(XImage)
    x11.XGetImage.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_int, ctypes.c_uint,
                              ctypes.c_uint, ctypes.c_ulong, ctypes.c_int]
    x11.XGetWindowAttributes.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(XWindowAttributes)]
    display = x11.XOpenDisplay(None)
    if not display:
        sys.exit("window_pixels.py: cannot open the X display")
    attributes = XWindowAttributes()
    x11.XGetWindowAttributes(display, window, ctypes.byref(attributes))
    w, h = attributes.width, attributes.height
    image = x11.XGetImage(display, window, 0, 0, w, h, 0xFFFFFFFF, 2).contents  # 2: ZPixmap
    if image.bits_per_pixel != 32:
        sys.exit(f"window_pixels.py: {image.bits_per_pixel} bits a pixel, 32 expected")
    rgb = bytearray()
    for y in range(h):
        row = ctypes.string_at(ctypes.addressof(image.data.contents) + y * image.bytes_per_line, 4 * w)
        for x in range(w):
            b, g, r = row[4 * x], row[4 * x + 1], row[4 * x + 2]
            rgb += bytes((r, g, b))
    with open(out, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (w, h) + bytes(rgb))


main()
