"""xscreen.py — what the X screen shows now, read straight from the server (XGetImage).

The editor's own screenshots (F12) wait for its next frame; timing how soon a click shows needs
a look from outside, as a person's eye would take it. ctypes and libX11 only: the test machines
have no python-xlib, xwd or ImageMagick.
"""
import ctypes
import ctypes.util
import os


class _XImage(ctypes.Structure):  # the fields of Xlib.h's XImage up to bits_per_pixel
    _fields_ = [('width', ctypes.c_int), ('height', ctypes.c_int), ('xoffset', ctypes.c_int),
                ('format', ctypes.c_int), ('data', ctypes.POINTER(ctypes.c_ubyte)),
                ('byte_order', ctypes.c_int), ('bitmap_unit', ctypes.c_int),
                ('bitmap_bit_order', ctypes.c_int), ('bitmap_pad', ctypes.c_int),
                ('depth', ctypes.c_int), ('bytes_per_line', ctypes.c_int),
                ('bits_per_pixel', ctypes.c_int)]


_ALL_PLANES = ctypes.c_ulong(0xFFFFFFFF)
_Z_PIXMAP = 2


class Region:
    """A grabbed rectangle; pixel(x, y) in screen coordinates gives (r, g, b)."""

    def __init__(self, x, y, width, height, data):
        self.x, self.y, self.width, self.height, self.data = x, y, width, height, data

    def pixel(self, x, y):
        i = ((y - self.y) * self.width + (x - self.x)) * 4
        b, g, r = self.data[i:i + 3]  # 24-bit TrueColor on a little-endian server: B G R X
        return r, g, b


class Screen:
    def __init__(self):
        self.x11 = ctypes.CDLL(ctypes.util.find_library('X11') or 'libX11.so.6')
        self.x11.XOpenDisplay.restype = ctypes.c_void_p
        self.x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
        self.x11.XDefaultRootWindow.restype = ctypes.c_ulong
        self.x11.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
        self.x11.XGetImage.restype = ctypes.POINTER(_XImage)
        self.x11.XGetImage.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_int,
                                       ctypes.c_uint, ctypes.c_uint, ctypes.c_ulong, ctypes.c_int]
        self.x11.XDestroyImage.argtypes = [ctypes.POINTER(_XImage)]
        self.display = self.x11.XOpenDisplay(os.environ.get('DISPLAY', '').encode())
        if not self.display:
            raise RuntimeError('cannot open the X display')
        self.root = self.x11.XDefaultRootWindow(self.display)

    def grab(self, x, y, width, height):
        """The screen's pixels in the rectangle, as the server holds them now."""
        img = self.x11.XGetImage(self.display, self.root, x, y, width, height, _ALL_PLANES, _Z_PIXMAP)
        if not img:
            raise RuntimeError('XGetImage failed')
        im = img.contents
        if im.bits_per_pixel != 32:
            self.x11.XDestroyImage(img)
            raise RuntimeError('expected a 32-bit TrueColor screen, got %d bits' % im.bits_per_pixel)
        stride = im.bytes_per_line
        raw = ctypes.string_at(im.data, stride * height)
        rows = b''.join(raw[r * stride:r * stride + width * 4] for r in range(height))
        self.x11.XDestroyImage(img)
        return Region(x, y, width, height, rows)


class _XClientMessageEvent(ctypes.Structure):  # Xlib.h's, padded to the XEvent union's size
    _fields_ = [('type', ctypes.c_int), ('serial', ctypes.c_ulong), ('send_event', ctypes.c_int),
                ('display', ctypes.c_void_p), ('window', ctypes.c_ulong),
                ('message_type', ctypes.c_ulong), ('format', ctypes.c_int),
                ('l', ctypes.c_long * 5), ('pad', ctypes.c_long * 12)]


def close_window(wid):
    """Asks window `wid` to close as a window manager's close button does: the WM_DELETE_WINDOW
    message of the WM_PROTOCOLS it takes part in (Xvfb runs no window manager)."""
    screen = Screen()
    x11, display = screen.x11, screen.display
    x11.XInternAtom.restype = ctypes.c_ulong
    x11.XInternAtom.argtypes = [ctypes.c_void_p, ctypes.c_char_p, ctypes.c_int]
    x11.XSendEvent.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_long,
                               ctypes.c_void_p]
    x11.XFlush.argtypes = [ctypes.c_void_p]
    event = _XClientMessageEvent(type=33, window=int(wid), format=32,  # 33: ClientMessage
                                 message_type=x11.XInternAtom(display, b'WM_PROTOCOLS', 0))
    event.l[0] = x11.XInternAtom(display, b'WM_DELETE_WINDOW', 0)
    if not x11.XSendEvent(display, int(wid), 0, 0, ctypes.byref(event)):
        raise RuntimeError('XSendEvent failed')
    x11.XFlush(display)


def save_png(region, path):
    """Writes a grabbed region as an 8-bit RGB PNG (to look at when a timing case fails)."""
    import struct
    import zlib
    rows = bytearray()
    for y in range(region.height):
        rows.append(0)
        for x in range(region.width):
            rows.extend(region.pixel(region.x + x, region.y + y))

    def chunk(kind, data):
        body = kind + data
        return struct.pack('>I', len(data)) + body + struct.pack('>I', zlib.crc32(body))

    header = struct.pack('>IIBBBBB', region.width, region.height, 8, 2, 0, 0, 0)
    with open(path, 'wb') as f:
        f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', header) +
                chunk(b'IDAT', zlib.compress(bytes(rows))) + chunk(b'IEND', b''))
