#!/usr/bin/env python3
"""tools/wireshark/slmp.lua against a capture slmp-sim records (--record-pcap).

Starts the real binary on free ports, holds a known exchange with it over TCP
and UDP (3E and 4E, binary and ASCII, a normal and an error response, a
request split across two TCP segments, two requests in one segment), stops it,
and has Debian's tshark decode the capture with the dissector: every field of
every message must come out as sent.

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


FIELDS = ["frame.number", "slmp.frame", "slmp.data_code", "slmp.serial", "slmp.command", "slmp.subcommand",
          "slmp.command_name", "slmp.device", "slmp.points", "slmp.word", "slmp.end_code",
          "slmp.end_code_meaning", "slmp.request_in", "slmp.response_in", "udp.srcport"]


def decode(pcap):
    """One dict of fields per SLMP message (a packet with two messages gives two)."""
    out = subprocess.run(["tshark", "-X", f"lua_script:{LUA}", "-2", "-r", pcap, "-Y", "slmp",
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


def compare(what, expected, messages):
    failures = []
    if len(messages) != len(expected):
        failures.append(f"{what}: {len(messages)} SLMP messages decoded, expected {len(expected)}:\n"
                        + "\n".join(str(m) for m in messages))
    keys = dict(frame="slmp.frame", code="slmp.data_code", serial="slmp.serial", command="slmp.command",
                sub="slmp.subcommand", name="slmp.command_name", device="slmp.device", points="slmp.points",
                words="slmp.word", end="slmp.end_code", meaning="slmp.end_code_meaning")
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


def main():
    with tempfile.TemporaryDirectory() as tmp:
        ready, pcap = os.path.join(tmp, "ready.json"), os.path.join(tmp, "session.pcap")
        sim = subprocess.Popen([SIM, "--tcp-port", "0", "--udp-port", "0", "--no-http", "--ready-file", ready,
                                "--record-pcap", pcap, "--log-level", "warn"])
        try:
            wait_for(lambda: os.path.exists(ready) and os.path.getsize(ready) > 0, "the ready file")
            with open(ready) as f:
                ports = json.load(f)
            converse(ports["tcp"][0], ports["udp"][0])
        finally:
            sim.send_signal(signal.SIGTERM)
            sim.wait(timeout=30)
        failures = compare("recorded session", LIVE, decode(pcap))
        synthetic = os.path.join(tmp, "segments.pcap")
        synthetic_capture(synthetic)
        reassembled = decode(synthetic)
        failures += compare("cut and joined segments", REASSEMBLED, reassembled)
    if failures:
        print("\n".join(failures))
        return 1
    print(f"ok: {len(LIVE)} recorded and {len(REASSEMBLED)} reassembled SLMP messages decoded field by field")
    return 0


if __name__ == "__main__":
    sys.exit(main())
