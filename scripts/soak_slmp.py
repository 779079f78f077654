"""SLMP client codec for scripts/soak.py: 3E/4E frames, binary and ASCII, over
TCP and UDP, for the commands the soak run drives. Python stdlib only.

Frame layouts: SLMP Reference Manual ch. 4 (frames), §5.2 (device access),
Appendix 1 (extended device specification) and §5.4–§5.10 (memory, extend
unit, remote, self test); docs/sources.md.
"""
import socket
import struct
import time

# symbol -> (binary code, radix, is_bit)
DEVICES = {
    'D': (0xA8, 10, False), 'W': (0xB4, 16, False), 'SD': (0xA9, 10, False),
    'M': (0x90, 10, True), 'B': (0xA0, 16, True), 'Y': (0x9D, 16, True), 'X': (0x9C, 16, True),
    'G': (0xAB, 10, False), 'SM': (0x91, 10, True),
}


class LinkError(Exception):
    """A request that got no proper answer: kind is timeout, eof, reset or garbage."""

    def __init__(self, kind, detail=''):
        super().__init__(f'{kind}: {detail}' if detail else kind)
        self.kind = kind


class Enc:
    """Builds the request data (command onward) in one data code."""

    def __init__(self, ascii_code):
        self.ascii = ascii_code
        self.parts = []

    def u8(self, v):
        self.parts.append(('%02X' % v) if self.ascii else struct.pack('<B', v))
        return self

    def u16(self, v):
        self.parts.append(('%04X' % v) if self.ascii else struct.pack('<H', v))
        return self

    def u32(self, v):
        self.parts.append(('%08X' % v) if self.ascii else struct.pack('<I', v))
        return self

    def raw(self, text_or_bytes):
        self.parts.append(text_or_bytes)
        return self

    def head(self, command, subcommand):
        return self.u16(command).u16(subcommand)

    def device(self, sym, number, iqr=False):
        code, radix, _ = DEVICES[sym]
        if self.ascii:
            width = 8 if iqr else 6
            digits = ('%0*X' if radix == 16 else '%0*d') % (width, number)
            self.parts.append(sym.ljust(4 if iqr else 2, '*') + digits)
        elif iqr:
            self.parts.append(struct.pack('<IH', number, code))
        else:
            self.parts.append(struct.pack('<I', number)[:3] + bytes([code]))
        return self

    def ext_device(self, sym, number, ext, direct, iqr):
        """Extended device specification (008x): U3\\G (Q form 0080) or U3E0\\G (iQ-R 0082)."""
        code = DEVICES[sym][0]
        if self.ascii:
            ext_text = 'U3E%X' % (ext & 0xF) if ext >= 0x3E0 else 'U%03X' % ext
            if iqr:
                self.parts.append('00' + ext_text + '0000' + sym.ljust(4, '*') + '%010d' % number + '0000')
            else:
                self.parts.append('00' + ext_text + '000' + sym.ljust(2, '*') + '%06d' % number + '000')
        elif iqr:
            self.parts.append(struct.pack('<HIHHHB', 0, number, code, 0, ext, direct))
        else:
            self.parts.append(struct.pack('<H', 0) + struct.pack('<I', number)[:3] + bytes([code]) +
                              struct.pack('<HHB', 0, ext, direct))
        return self

    def words(self, values):
        for v in values:
            self.u16(v & 0xFFFF)
        return self

    def bits(self, values):
        """Bit units: ASCII one character a point; binary a nibble, first point high."""
        if self.ascii:
            self.parts.append(''.join('1' if v else '0' for v in values))
        else:
            out = bytearray()
            for i in range(0, len(values), 2):
                hi = 1 if values[i] else 0
                lo = 1 if i + 1 < len(values) and values[i + 1] else 0
                out.append(hi << 4 | lo)
            self.parts.append(bytes(out))
        return self

    def data(self):
        if self.ascii:
            return ''.join(self.parts)
        return b''.join(self.parts)


class Dec:
    """Reads the response data (after the end code) in one data code."""

    def __init__(self, data, ascii_code):
        self.data = data
        self.ascii = ascii_code
        self.pos = 0

    def _take(self, nbytes):
        width = nbytes * 2 if self.ascii else nbytes
        if self.pos + width > len(self.data):
            raise LinkError('garbage', f'response data too short ({len(self.data)} {"chars" if self.ascii else "bytes"})')
        chunk = self.data[self.pos:self.pos + width]
        self.pos += width
        return chunk

    def uint(self, nbytes):
        chunk = self._take(nbytes)
        if self.ascii:
            return int(chunk.decode(), 16)
        return int.from_bytes(chunk, 'little')

    def words(self, n):
        return [self.uint(2) for _ in range(n)]

    def dwords(self, n):
        return [self.uint(4) for _ in range(n)]

    def bytes_(self, n):
        if self.ascii:
            return bytes(self.uint(1) for _ in range(n))
        return bytes(self._take(n))

    def text(self, nchars):
        chunk = self.data[self.pos:self.pos + nchars]
        self.pos += nchars
        return bytes(chunk).decode('latin-1')

    def bits(self, n):
        if self.ascii:
            chunk = self.data[self.pos:self.pos + n]
            self.pos += n
            if len(chunk) != n:
                raise LinkError('garbage', 'bit data too short')
            return [1 if c == ord('1') else 0 for c in chunk]
        chunk = self._take((n + 1) // 2)
        out = []
        for b in chunk:
            out.append(b >> 4 & 1)
            out.append(b & 1)
        return out[:n]

    def done(self):
        if self.pos != len(self.data):
            raise LinkError('garbage', f'{len(self.data) - self.pos} unexpected trailing data')


def words_to_bits(words, n):
    """Word units of a bit device: bit 0 of the first word is the lowest device."""
    out = []
    for w in words:
        out.extend((w >> i) & 1 for i in range(16))
    return out[:n]


def bits_to_words(bits):
    out = []
    for i in range(0, len(bits), 16):
        w = 0
        for j, b in enumerate(bits[i:i + 16]):
            w |= (1 if b else 0) << j
        out.append(w)
    return out


class Link:
    """One client connection (TCP) or socket (UDP) to the simulator on 127.0.0.1."""

    def __init__(self, port, udp=False, timeout=2.0):
        self.port = port
        self.udp = udp
        self.timeout = timeout
        self.sock = None
        self.serial = 0

    def connect(self):
        self.close()
        kind = socket.SOCK_DGRAM if self.udp else socket.SOCK_STREAM
        s = socket.socket(socket.AF_INET, kind)
        s.settimeout(self.timeout)
        try:
            s.connect(('127.0.0.1', self.port))
        except ConnectionRefusedError as e:
            s.close()
            raise LinkError('refused', str(e))
        except socket.timeout:
            s.close()
            raise LinkError('timeout', 'connect')
        if not self.udp:
            s.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self.sock = s

    def close(self):
        if self.sock is not None:
            try:
                self.sock.close()
            except OSError:
                pass
            self.sock = None

    def _recv_exact(self, n, deadline):
        buf = bytearray()
        while len(buf) < n:
            left = deadline - time.monotonic()
            if left <= 0:
                raise LinkError('timeout', f'{len(buf)}/{n} bytes')
            self.sock.settimeout(left)
            try:
                chunk = self.sock.recv(n - len(buf))
            except socket.timeout:
                raise LinkError('timeout', f'{len(buf)}/{n} bytes')
            except ConnectionResetError:
                raise LinkError('reset')
            if not chunk:
                raise LinkError('eof', f'after {len(buf)}/{n} bytes')
            buf += chunk
        return bytes(buf)

    def request(self, body, ascii_code=False, e4=False):
        """Sends one request (body = Enc.data(): command, subcommand, data) and
        returns (end_code, Dec of the response data). Raises LinkError."""
        if self.sock is None:
            self.connect()
        serial = None
        if e4:
            self.serial = (self.serial + 1) & 0xFFFF
            serial = self.serial
        if ascii_code:
            text = (('5400%04X0000' % serial) if e4 else '5000') + '00FF03FF00' + '%04X' % (len(body) + 4) + '0010' + body
            frame = text.encode()
        else:
            sub = (b'\x54\x00' + struct.pack('<H', serial) + b'\x00\x00') if e4 else b'\x50\x00'
            frame = sub + b'\x00\xff\xff\x03\x00' + struct.pack('<HH', len(body) + 2, 0x10) + body
        try:
            self.sock.sendall(frame)
        except (BrokenPipeError, ConnectionResetError):
            raise LinkError('reset', 'send')
        except socket.timeout:
            raise LinkError('timeout', 'send')
        deadline = time.monotonic() + self.timeout
        if ascii_code:
            head_len = 26 if e4 else 18
        else:
            head_len = 13 if e4 else 9
        if self.udp:
            while True:
                left = deadline - time.monotonic()
                if left <= 0:
                    raise LinkError('timeout', 'udp')
                self.sock.settimeout(left)
                try:
                    dgram = self.sock.recv(65536)
                except socket.timeout:
                    raise LinkError('timeout', 'udp')
                except ConnectionRefusedError:
                    raise LinkError('refused', 'udp port unreachable')
                if e4 and len(dgram) >= head_len:   # a late answer carries another serial
                    got = int(dgram[4:8].decode(), 16) if ascii_code else struct.unpack_from('<H', dgram, 2)[0]
                    if got != serial:
                        continue
                break
            head, rest = dgram[:head_len], dgram[head_len:]
        else:
            head = self._recv_exact(head_len, deadline)
            rest = None
        if ascii_code:
            try:
                text = head.decode('ascii')
                want = (('D400%04X0000' % serial) if e4 else 'D000') + '00FF03FF00'
                if text[:len(want)] != want:
                    raise LinkError('garbage', f'response header {text!r}')
                length = int(text[-4:], 16)
            except (UnicodeDecodeError, ValueError):
                raise LinkError('garbage', f'response header {head!r}')
        else:
            want = ((b'\xd4\x00' + struct.pack('<H', serial) + b'\x00\x00') if e4 else b'\xd0\x00') + b'\x00\xff\xff\x03\x00'
            if head[:len(want)] != want:
                raise LinkError('garbage', f'response header {head.hex()}')
            length = struct.unpack_from('<H', head, head_len - 2)[0]
        if rest is None:
            rest = self._recv_exact(length, deadline)
        elif len(rest) != length:
            raise LinkError('garbage', f'datagram holds {len(rest)} after the header, length field says {length}')
        end_width = 4 if ascii_code else 2
        if length < end_width:
            raise LinkError('garbage', f'response data length {length}')
        if ascii_code:
            try:
                end_code = int(rest[:4].decode('ascii'), 16)
            except (UnicodeDecodeError, ValueError):
                raise LinkError('garbage', f'end code {rest[:4]!r}')
        else:
            end_code = struct.unpack_from('<H', rest, 0)[0]
        return end_code, Dec(rest[end_width:], ascii_code)
