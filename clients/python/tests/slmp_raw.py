"""A tiny SLMP client for the tests: the "client under test" that writes words (3E binary frame, 1401)."""
import socket
import struct

DEVICE_CODES = {"D": 0xA8, "M": 0x90, "W": 0xB4}


def write_words(port, device, number, values, host="127.0.0.1"):
    """Device Write (1401/0000) of word values at device+number; returns the end code."""
    data = struct.pack("<HH", 0x1401, 0x0000) + struct.pack("<I", number)[:3] + bytes([DEVICE_CODES[device]])
    data += struct.pack("<H", len(values)) + b"".join(struct.pack("<H", v & 0xFFFF) for v in values)
    body = struct.pack("<H", 0x0010) + data                       # monitoring timer 4 s
    frame = bytes([0x50, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00]) + struct.pack("<H", len(body)) + body
    with socket.create_connection((host, port), timeout=10) as s:
        s.sendall(frame)
        head = _exactly(s, 9)
        length = struct.unpack_from("<H", head, 7)[0]
        rest = _exactly(s, length)
        return struct.unpack_from("<H", rest, 0)[0]


def _exactly(s, n):
    out = b""
    while len(out) < n:
        chunk = s.recv(n - len(out))
        if not chunk:
            raise ConnectionError("the PLC closed the connection")
        out += chunk
    return out
