#!/usr/bin/env python3
"""tools/wireshark/slmp.lua against a capture slmp-sim records (--record-pcap).

Starts the real binary on free ports, holds a known exchange with it over TCP
and UDP (3E and 4E, binary and ASCII, a normal and an error response, a
request split across two TCP segments, two requests in one segment), stops it,
and has Debian's tshark decode the capture with the dissector: every field of
every message must come out as sent. Then the same for a 1E session (binary
and ASCII, a profile that serves 1E) and a station-number-extended session
(the RJ71GN11-T2 profile), and an FX5U session decoded with the "X/Y in octal"
preference.

Usage: check_dissector.py SLMP_SIM_BINARY DISSECTOR_LUA
Exit 0 on success; prints every mismatch and exits 1 otherwise.
"""
import json
import os
import signal
import socket
import subprocess
import sys
import tempfile
import time

SIM, LUA = sys.argv[1], sys.argv[2]
if subprocess.run(["sh", "-c", "command -v tshark"], capture_output=True).returncode != 0:
    sys.exit("tshark is not installed: install Debian's tshark package (scripts/setup.sh does)")


def wait_for(predicate, what, timeout=30.0):
    """Waits for an explicit condition (never a fixed time)."""
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            sys.exit(f"timed out waiting for {what}")
        time.sleep(0.02)


def frame_3e_binary(command, subcommand, data):
    body = bytes([0x10, 0x00]) + command.to_bytes(2, "little") + subcommand.to_bytes(2, "little") + data
    return bytes([0x50, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00]) + len(body).to_bytes(2, "little") + body


def frame_4e_binary(serial, command, subcommand, data):
    body = bytes([0x10, 0x00]) + command.to_bytes(2, "little") + subcommand.to_bytes(2, "little") + data
    return (bytes([0x54, 0x00]) + serial.to_bytes(2, "little") + bytes([0, 0, 0x00, 0xFF, 0xFF, 0x03, 0x00])
            + len(body).to_bytes(2, "little") + body)


def frame_3e_ascii(text):
    """text: timer, command, subcommand and data as ASCII hex."""
    return ("500000FF03FF00" + f"{len(text):04X}" + text).encode()


def frame_ext(serial, command, subcommand, data, station=0xFF, extended=0x0000):
    """The station-number-extended frame (68 00; docs/frames.md)."""
    body = (bytes([0x10, 0x00]) + command.to_bytes(2, "little") + subcommand.to_bytes(2, "little") + bytes(6)
            + data)
    return (bytes([0x68, 0x00]) + serial.to_bytes(2, "little") + bytes([0, 0, 0x00, station, 0xFF, 0x03, 0x00, 0x00])
            + extended.to_bytes(2, "little") + len(body).to_bytes(2, "little") + body)


def read_exactly(sock, n):
    data = b""
    while len(data) < n:
        chunk = sock.recv(n - len(data))
        if not chunk:
            sys.exit("connection closed early")
        data += chunk
    return data


def binary_response(sock, four_e=False):
    head = read_exactly(sock, 13 if four_e else 9)
    return head + read_exactly(sock, int.from_bytes(head[-2:], "little"))


def ascii_response(sock):
    head = read_exactly(sock, 18)
    return head + read_exactly(sock, int(head[14:18], 16))


def converse(tcp_port, udp_port):
    """The known exchange. Returns nothing: the capture is the record."""
    with socket.create_connection(("127.0.0.1", tcp_port)) as s:
        # 1401 Device Write (words, Q form) D100 = 1, 2, 3; then 0401 read them.
        s.sendall(frame_3e_binary(0x1401, 0x0000, bytes([100, 0, 0, 0xA8, 3, 0, 1, 0, 2, 0, 3, 0])))
        binary_response(s)
        s.sendall(frame_3e_binary(0x0401, 0x0000, bytes([100, 0, 0, 0xA8, 3, 0])))
        binary_response(s)
        # A command the table does not have: C059 with error information.
        s.sendall(frame_3e_binary(0x0999, 0x0000, b""))
        binary_response(s)
        # Two 4E requests sent together, answered by serial.
        s.sendall(frame_4e_binary(0x1234, 0x0401, 0x0000, bytes([100, 0, 0, 0xA8, 1, 0]))
                  + frame_4e_binary(0x1235, 0x0101, 0x0000, b""))
        binary_response(s, four_e=True)
        binary_response(s, four_e=True)
        # iQ-R form: X10 x2 (4-byte number, 2-byte code).
        s.sendall(frame_3e_binary(0x0401, 0x0002, bytes([0x10, 0, 0, 0, 0x9C, 0x00, 2, 0])))
        binary_response(s)
        # ASCII: 0401 word read of D100 x2 (Q form: "D*" + 6 digits).
        s.sendall(frame_3e_ascii("0010" "0401" "0000" "D*000100" "0002"))
        ascii_response(s)
        # ASCII 4E: serial 00AB, Read Type Name.
        s.sendall(("5400" "00AB" "0000" "00FF03FF00" "000C" "0010" "0101" "0000").encode())
        head = read_exactly(s, 26)
        read_exactly(s, int(head[22:26], 16))
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as u:
        u.settimeout(10)
        u.sendto(frame_3e_binary(0x0403, 0x0000, bytes([1, 1, 100, 0, 0, 0xA8, 102, 0, 0, 0xA8])),
                 ("127.0.0.1", udp_port))
        u.recvfrom(4096)


def converse_1e(tcp_port, udp_port):
    """A 1E session (docs/frames.md): a 1E response has no length field, so
    each answer's length is the one the exchange expects."""
    d100 = bytes([100, 0, 0, 0, 0x20, 0x44])      # D100: number (4), code "D " (2)
    m0 = bytes([0, 0, 0, 0, 0x20, 0x4D])          # M0
    with socket.create_connection(("127.0.0.1", tcp_port), timeout=10) as s:
        exchanges = [
            (bytes([0x03, 0xFF, 0x0A, 0x00]) + d100 + bytes([3, 0, 1, 0, 2, 0, 3, 0]), 2),   # write D100-D102
            (bytes([0x01, 0xFF, 0x0A, 0x00]) + d100 + bytes([3, 0]), 8),                    # read them
            (bytes([0x02, 0xFF, 0x0A, 0x00]) + m0 + bytes([3, 0, 0x10, 0x10]), 2),          # M0-M2 = 1, 0, 1
            (bytes([0x00, 0xFF, 0x0A, 0x00]) + m0 + bytes([3, 0]), 4),                      # read them
            (bytes([0x04, 0xFF, 0x0A, 0x00, 1, 0]) + bytes([5, 0, 0, 0, 0x20, 0x4D, 1]), 2),  # test: M5 on
            (bytes([0x07, 0xFF, 0x0A, 0x00, 2, 0]) + d100 + bytes([200, 0, 0, 0, 0x20, 0x44]), 2),  # register D100, D200
            (bytes([0x01, 0xFF, 0x0A, 0x00]) + bytes([0xFF, 0xFF, 0, 0, 0x20, 0x44]) + bytes([2, 0]), 2),  # D65535 x2: 57
            (bytes([0x15, 0xFF, 0x0A, 0x00]), 3),                                             # PC type
            (bytes([0x16, 0xFF, 0x0A, 0x00, 5]) + b"ABCDE", 8),                               # loopback
        ]
        for request, answer in exchanges:
            s.sendall(request)
            read_exactly(s, answer)
        # ASCII: test (word units) D200 = 1234H, the monitor of the registration above, a read.
        s.sendall(b"05FF000A" b"0100" b"4420" b"000000C8" b"1234")
        read_exactly(s, 4)
        s.sendall(b"09FF000A")
        read_exactly(s, 12)
        s.sendall(b"01FF000A" b"4420" b"00000064" b"0200")
        read_exactly(s, 12)
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as u:
        u.settimeout(10)
        u.sendto(bytes([0x01, 0xFF, 0x0A, 0x00]) + d100 + bytes([1, 0]), ("127.0.0.1", udp_port))
        u.recvfrom(4096)


def converse_ext(tcp_port):
    """A station-number-extended session: write and read D100 (station FF,
    extended 0000), the own station by its extended number (7C, FFFF), and
    another station (7C, 0005) answered 4A02 with its error information."""
    with socket.create_connection(("127.0.0.1", tcp_port), timeout=10) as s:
        def exchange(frame):
            s.sendall(frame)
            head = read_exactly(s, 16)
            read_exactly(s, int.from_bytes(head[-2:], "little"))
        exchange(frame_ext(0x1234, 0x1401, 0x0000, bytes([100, 0, 0, 0xA8, 2, 0, 0x34, 0x12, 0x78, 0x56])))
        exchange(frame_ext(0x1235, 0x0401, 0x0000, bytes([100, 0, 0, 0xA8, 2, 0]), station=0x7C, extended=0xFFFF))
        exchange(frame_ext(0x1236, 0x0401, 0x0000, bytes([100, 0, 0, 0xA8, 1, 0]), station=0x7C, extended=0x0005))


def converse_octal(tcp_port):
    """An FX5U session decoded with the "X/Y in octal" preference: bit index 8
    written in binary (X10 in octal, X8 in hex) and X*000010 in ASCII."""
    with socket.create_connection(("127.0.0.1", tcp_port), timeout=10) as s:
        s.sendall(frame_3e_binary(0x1401, 0x0001, bytes([8, 0, 0, 0x9C, 2, 0, 0x11])))
        binary_response(s)
        s.sendall(frame_3e_ascii("001014010001X*0000100001" + "1"))
        ascii_response(s)


FIELDS = ["frame.number", "slmp.frame", "slmp.data_code", "slmp.serial", "slmp.command", "slmp.subcommand",
          "slmp.command_name", "slmp.device", "slmp.points", "slmp.word", "slmp.end_code",
          "slmp.end_code_meaning", "slmp.request_in", "slmp.response_in", "udp.srcport"]


def decode(pcap, ports=None, xy_octal=False):
    """One dict of fields per SLMP message (a packet with two messages gives two).
    `ports`: the SLMP ports preference (a 1E frame is decoded only there);
    `xy_octal`: the "X/Y in octal (iQ-F)" preference."""
    prefs = ["-o", f"slmp.ports:{ports}"] if ports else []
    if xy_octal:
        prefs += ["-o", "slmp.xy_octal:TRUE"]
    out = subprocess.run(["tshark", "-X", f"lua_script:{LUA}", *prefs, "-2", "-r", pcap, "-Y", "slmp",
                          "-T", "json", "--no-duplicate-keys", "-J", "frame udp slmp"],
                         capture_output=True, text=True, check=False)
    if out.returncode != 0 or "rror" in out.stderr:
        sys.exit(f"tshark failed ({out.returncode}):\n{out.stderr}")
    messages = []
    for packet in json.loads(out.stdout or "[]"):
        layers = packet["_source"]["layers"]
        slmp = layers.get("slmp")
        if slmp is None:
            continue
        for message in slmp if isinstance(slmp, list) else [slmp]:
            fields = flatten(message)
            fields["frame.number"] = layers["frame"]["frame.number"]
            fields["udp"] = "udp" in layers
            messages.append(fields)
    return messages


def flatten(tree):
    """{"slmp.device": [...] or "..."} at any depth, repeated fields joined with ","."""
    fields = {}

    def walk(node):
        for key, value in node.items():
            if isinstance(value, dict):
                walk(value)
            elif key.startswith("slmp."):
                values = value if isinstance(value, list) else [value]
                fields[key] = ",".join(filter(None, [fields.get(key)] + [str(v) for v in values]))
    walk(tree)
    return fields


LIVE = [
    dict(frame="3E request", code="binary", command="0x1401", sub="0x0000",
         name="Device Write (word units, Q form)", device="D100", points="3"),
    dict(frame="3E response", code="binary", command="0x1401", end="0x0000", meaning="normal completion"),
    dict(frame="3E request", code="binary", command="0x0401", sub="0x0000",
         name="Device Read (word units, Q form)", device="D100", points="3"),
    dict(frame="3E response", code="binary", command="0x0401", end="0x0000", words="0x0001,0x0002,0x0003"),
    dict(frame="3E request", code="binary", command="0x0999", name="not in slmp-sim's command table"),
    dict(frame="3E response", code="binary", end="0xc059", meaning_contains="not supported"),
    dict(frame="4E request", code="binary", serial="0x1234", command="0x0401", device="D100", points="1"),
    dict(frame="4E response", code="binary", serial="0x1234", command="0x0401", end="0x0000", words="0x0001"),
    dict(frame="4E request", code="binary", serial="0x1235", command="0x0101", name="Read Type Name"),
    dict(frame="4E response", code="binary", serial="0x1235", command="0x0101", end="0x0000"),
    dict(frame="3E request", code="binary", command="0x0401", sub="0x0002",
         name="Device Read (word units, iQ-R form)", device="X10", points="2"),
    dict(frame="3E response", code="binary", command="0x0401", end="0x0000"),
    dict(frame="3E request", code="ASCII", command="0x0401", name="Device Read (word units, Q form)",
         device="D100", points="2"),
    dict(frame="3E response", code="ASCII", command="0x0401", end="0x0000", words="0x0001,0x0002"),
    dict(frame="4E request", code="ASCII", serial="0x00ab", command="0x0101", name="Read Type Name"),
    dict(frame="4E response", code="ASCII", serial="0x00ab", command="0x0101", end="0x0000"),
    dict(frame="3E request", code="binary", command="0x0403", name="Read Random (Q form)",
         device="D100,D102", udp=True),
    dict(frame="3E response", code="binary", command="0x0403", end="0x0000", udp=True),
]


ONE_E = [
    dict(frame="1E request", code="binary", cmd1e="0x03", command="0x1401", sub="0x0000",
         name="Batch Write (word units)", device="D100", points="3", words="0x0001,0x0002,0x0003"),
    dict(frame="1E response", code="binary", cmd1e="0x83", end1e="0x00", meaning="normal completion"),
    dict(frame="1E request", code="binary", cmd1e="0x01", command="0x0401", name="Batch Read (word units)",
         device="D100", points="3"),
    dict(frame="1E response", code="binary", cmd1e="0x81", end1e="0x00", words="0x0001,0x0002,0x0003"),
    dict(frame="1E request", code="binary", cmd1e="0x02", command="0x1401", sub="0x0001",
         name="Batch Write (bit units)", device="M0", points="3", bits="101"),
    dict(frame="1E response", code="binary", cmd1e="0x82", end1e="0x00"),
    dict(frame="1E request", code="binary", cmd1e="0x00", name="Batch Read (bit units)", device="M0", points="3"),
    dict(frame="1E response", code="binary", cmd1e="0x80", end1e="0x00", bits="101"),
    dict(frame="1E request", code="binary", cmd1e="0x04", command="0x1402", sub="0x0001",
         name="Test (random write, bit units)", device="M5", points="1", value="0x00000001"),
    dict(frame="1E response", code="binary", cmd1e="0x84", end1e="0x00"),
    dict(frame="1E request", code="binary", cmd1e="0x07", command="0x0801",
         name="Monitor Device Registration (word units)", device="D100,D200", points="2"),
    dict(frame="1E response", code="binary", cmd1e="0x87", end1e="0x00"),
    dict(frame="1E request", code="binary", cmd1e="0x01", device="D65535", points="2"),
    dict(frame="1E response", code="binary", cmd1e="0x81", end1e="0x57", meaning="points or device range exceeded"),
    dict(frame="1E request", code="binary", cmd1e="0x15", command="0x0101", name="PC Type Read"),
    dict(frame="1E response", code="binary", cmd1e="0x95", end1e="0x00", pc_type="0x41"),
    dict(frame="1E request", code="binary", cmd1e="0x16", command="0x0619", name="Loopback Test", points="5",
         loopback="ABCDE"),
    dict(frame="1E response", code="binary", cmd1e="0x96", end1e="0x00", points="5", loopback="ABCDE"),
    dict(frame="1E request", code="ASCII", cmd1e="0x05", command="0x1402", sub="0x0000",
         name="Test (random write, word units)", device="D200", points="1", value="0x00001234"),
    dict(frame="1E response", code="ASCII", cmd1e="0x85", end1e="0x00"),
    dict(frame="1E request", code="ASCII", cmd1e="0x09", command="0x0802", name="Monitor (word units)"),
    dict(frame="1E response", code="ASCII", cmd1e="0x89", end1e="0x00", words="0x0001,0x1234"),
    dict(frame="1E request", code="ASCII", cmd1e="0x01", device="D100", points="2"),
    dict(frame="1E response", code="ASCII", cmd1e="0x81", end1e="0x00", words="0x0001,0x0002"),
    dict(frame="1E request", code="binary", cmd1e="0x01", device="D100", points="1", udp=True),
    dict(frame="1E response", code="binary", cmd1e="0x81", end1e="0x00", words="0x0001", udp=True),
]

EXTENDED = [
    dict(frame="station-extended request", code="binary", serial="0x1234", ext="0x0000", command="0x1401",
         name="Device Write (word units, Q form)", device="D100", points="2"),
    dict(frame="station-extended response", code="binary", serial="0x1234", command="0x1401", sub="0x0000",
         end="0x0000"),
    dict(frame="station-extended request", code="binary", serial="0x1235", station="0x7c", ext="0xffff",
         command="0x0401", device="D100", points="2"),
    dict(frame="station-extended response", code="binary", serial="0x1235", end="0x0000", words="0x1234,0x5678"),
    dict(frame="station-extended request", code="binary", serial="0x1236", station="0x7c", ext="0x0005",
         command="0x0401", device="D100", points="1"),
    dict(frame="station-extended response", code="binary", serial="0x1236", command="0x0401", end="0x4a02",
         station="0x7c,0x7c", ext="0x0005,0x0005"),
]


OCTAL = [
    dict(frame="3E request", code="binary", command="0x1401", sub="0x0001", device="X10", points="2"),
    dict(frame="3E response", code="binary", command="0x1401", end="0x0000"),
    dict(frame="3E request", code="ASCII", command="0x1401", sub="0x0001", device="X10", points="1"),
    dict(frame="3E response", code="ASCII", command="0x1401", end="0x0000"),
]


def compare(what, expected, messages):
    failures = []
    if len(messages) != len(expected):
        failures.append(f"{what}: {len(messages)} SLMP messages decoded, expected {len(expected)}:\n"
                        + "\n".join(str(m) for m in messages))
    keys = dict(frame="slmp.frame", code="slmp.data_code", serial="slmp.serial", command="slmp.command",
                sub="slmp.subcommand", name="slmp.command_name", device="slmp.device", points="slmp.points",
                words="slmp.word", end="slmp.end_code", meaning="slmp.end_code_meaning", cmd1e="slmp.command_1e",
                end1e="slmp.end_code_1e", bits="slmp.bits", value="slmp.value", pc_type="slmp.pc_type",
                loopback="slmp.loopback", ext="slmp.extended_station", station="slmp.station")
    for i, (want, got) in enumerate(zip(expected, messages)):
        where = f"{what}, message {i + 1} (frame {got['frame.number']})"
        for key, field in keys.items():
            if key in want and got.get(field, "").lower() != want[key].lower():
                failures.append(f"{where}: {field} is {got.get(field)!r}, expected {want[key]!r}")
        if "meaning_contains" in want and want["meaning_contains"] not in got.get("slmp.end_code_meaning", ""):
            failures.append(f"{where}: slmp.end_code_meaning is {got.get('slmp.end_code_meaning')!r}")
        if want.get("udp", False) != got["udp"]:
            failures.append(f"{where}: decoded over {'UDP' if got['udp'] else 'TCP'}")
        # Every response names the request it answers, every answered request its response.
        link = "slmp.request_in" if want["frame"].endswith("response") else "slmp.response_in"
        if not got.get(link):
            failures.append(f"{where}: no {link}")
    return failures


def synthetic_capture(path):
    """A capture of cut and joined TCP segments, which slmp-sim's recorder never
    writes (it writes each message whole): a request cut after 5 bytes whose
    rest shares a segment with a second request, then both responses in one
    segment. LINKTYPE_RAW IPv4; tshark does not check these checksums."""
    client, server = (bytes([127, 0, 0, 1]), 40000), (bytes([127, 0, 0, 1]), 5000)
    seq = {client: 1000, server: 5000}
    packets = []

    def segment(src, dst, flags, payload=b""):
        tcp = (src[1].to_bytes(2, "big") + dst[1].to_bytes(2, "big") + seq[src].to_bytes(4, "big")
               + seq[dst].to_bytes(4, "big") + bytes([0x50, flags]) + (65535).to_bytes(2, "big") + bytes(4))
        ip = (bytes([0x45, 0]) + (20 + len(tcp) + len(payload)).to_bytes(2, "big") + bytes([0, 0, 0x40, 0, 64, 6, 0, 0])
              + src[0] + dst[0])
        packets.append(ip + tcp + payload)
        seq[src] += len(payload) + (1 if flags & 0x02 else 0)

    first = frame_3e_binary(0x0401, 0x0000, bytes([100, 0, 0, 0xA8, 3, 0]))
    second = frame_3e_binary(0x0401, 0x0000, bytes([200, 0, 0, 0xA8, 1, 0]))
    segment(client, server, 0x02)
    segment(server, client, 0x12)
    segment(client, server, 0x10)
    segment(client, server, 0x18, first[:5])
    segment(client, server, 0x18, first[5:] + second)
    answer = bytes([0xD0, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00])
    segment(server, client, 0x18, answer + bytes([8, 0, 0, 0, 1, 0, 2, 0, 3, 0]) + answer + bytes([4, 0, 0, 0, 9, 0]))
    with open(path, "wb") as out:
        out.write(bytes.fromhex("d4c3b2a1") + (2).to_bytes(2, "little") + (4).to_bytes(2, "little") + bytes(8)
                  + (65535).to_bytes(4, "little") + (101).to_bytes(4, "little"))
        for i, packet in enumerate(packets):
            out.write((1700000000 + i).to_bytes(4, "little") + bytes(4) + len(packet).to_bytes(4, "little") * 2
                      + packet)


REASSEMBLED = [
    dict(frame="3E request", command="0x0401", device="D100", points="3"),
    dict(frame="3E request", command="0x0401", device="D200", points="1"),
    dict(frame="3E response", command="0x0401", end="0x0000", words="0x0001,0x0002,0x0003"),
    dict(frame="3E response", command="0x0401", end="0x0000", words="0x0009"),
]


def record(tmp, name, profile, converse_with):
    """Runs slmp-sim with `profile`, holds `converse_with(tcp, udp)` with it;
    returns the capture and the TCP and UDP ports."""
    ready, pcap = os.path.join(tmp, name + ".json"), os.path.join(tmp, name + ".pcap")
    sim = subprocess.Popen([SIM, "--profile", profile, "--tcp-port", "0", "--udp-port", "0", "--no-http",
                            "--ready-file", ready, "--record-pcap", pcap, "--log-level", "warn"])
    try:
        wait_for(lambda: os.path.exists(ready) and os.path.getsize(ready) > 0, "the ready file")
        with open(ready) as f:
            ports = json.load(f)
        converse_with(ports["tcp"][0], ports["udp"][0])
    finally:
        sim.send_signal(signal.SIGTERM)
        sim.wait(timeout=30)
    return pcap, ports["tcp"][0], ports["udp"][0]


def main():
    with tempfile.TemporaryDirectory() as tmp:
        pcap, _, _ = record(tmp, "session", "R08CPU", converse)
        failures = compare("recorded session", LIVE, decode(pcap))
        pcap, tcp, udp = record(tmp, "session-1e", "Q06UDVCPU-QJ71E71", converse_1e)
        failures += compare("recorded 1E session", ONE_E, decode(pcap, f"{tcp},{udp}"))
        pcap, _, _ = record(tmp, "session-ext", "RJ71GN11-T2", lambda tcp, udp: converse_ext(tcp))
        failures += compare("recorded station-number-extended session", EXTENDED, decode(pcap))
        pcap, _, _ = record(tmp, "session-octal", "FX5U-32MR", lambda tcp, udp: converse_octal(tcp))
        failures += compare("recorded FX5U session, X/Y in octal", OCTAL, decode(pcap, xy_octal=True))
        synthetic = os.path.join(tmp, "segments.pcap")
        synthetic_capture(synthetic)
        reassembled = decode(synthetic)
        failures += compare("cut and joined segments", REASSEMBLED, reassembled)
    if failures:
        print("\n".join(failures))
        return 1
    print(f"ok: {len(LIVE)} 3E/4E, {len(ONE_E)} 1E, {len(EXTENDED)} station-number-extended, {len(OCTAL)} FX5U "
          f"octal recorded and "
          f"{len(REASSEMBLED)} reassembled SLMP messages decoded field by field")
    return 0


if __name__ == "__main__":
    sys.exit(main())
