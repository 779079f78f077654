#!/usr/bin/env python3
"""Writes the committed seed corpora under tests/fuzz/corpus/ (run from anywhere).

The engine seeds are whole SLMP requests for every command family, in the four
frame shapes (3E/4E x binary/ASCII), encoded here independently of protocol/
from the field rules of the SLMP Reference Manual. Seeds only
steer the fuzzer: a wrong one costs coverage, never a false finding.
"""
import json
import pathlib
import re
import shutil

ROOT = pathlib.Path(__file__).resolve().parent
REPO = ROOT.parent.parent
CORPUS = ROOT / "corpus"

# (binary Q code, ASCII Q code, iQ-R code, ASCII radix)
DEVICES = {
    "D": (0xA8, "D*", 0x00A8, 10), "M": (0x90, "M*", 0x0090, 10), "W": (0xB4, "W*", 0x00B4, 16),
    "X": (0x9C, "X*", 0x009C, 16), "Y": (0x9D, "Y*", 0x009D, 16), "B": (0xA0, "B*", 0x00A0, 16),
    "ZR": (0xB0, "ZR", 0x00B0, 10), "R": (0xAF, "R*", 0x00AF, 10), "TN": (0xC2, "TN", 0x00C2, 10),
    "SM": (0x91, "SM", 0x0091, 10), "SD": (0xA9, "SD", 0x00A9, 10), "L": (0x92, "L*", 0x0092, 10),
    "Z": (0xCC, "Z*", 0x00CC, 10), "CN": (0xC5, "CN", 0x00C5, 10), "TS": (0xC1, "TS", 0x00C1, 10),
}


class Codec:
    def __init__(self, ascii):
        self.ascii = ascii

    def num(self, value, nbytes):
        if self.ascii:
            return ("%0*X" % (nbytes * 2, value)).encode()
        return value.to_bytes(nbytes, "little")

    def device(self, name, number, iqr=False):
        q_code, ascii_q, iqr_code, radix = DEVICES[name]
        if self.ascii:
            code = name.ljust(4, "*") if iqr else ascii_q
            digits = 8 if iqr else 6
            text = ""
            n = number
            while n:
                text = "0123456789ABCDEF"[n % radix] + text
                n //= radix
            return (code + text.rjust(digits, "0")).encode()
        if iqr:
            return number.to_bytes(4, "little") + iqr_code.to_bytes(2, "little")
        return number.to_bytes(3, "little") + bytes([q_code])

    def bits(self, points):
        if self.ascii:
            return "".join("1" if p else "0" for p in points).encode()
        out = bytearray()
        for i in range(0, len(points), 2):
            hi = 0x10 if points[i] else 0
            lo = 0x01 if i + 1 < len(points) and points[i + 1] else 0
            out.append(hi | lo)
        return bytes(out)

    def raw(self, data):
        return data


def frame(c, e4, command, subcommand, body, serial=0x1234, route=(0x00, 0xFF, 0x03FF, 0x00), timer=0x0010):
    data = c.num(timer, 2) + c.num(command, 2) + c.num(subcommand, 2) + body
    head = c.num(0x54 if e4 else 0x50, 1) + c.num(0, 1)
    if e4:
        head += c.num(serial, 2) + c.num(0, 2)
    net, st, io, md = route
    head += c.num(net, 1) + c.num(st, 1) + c.num(io, 2) + c.num(md, 1)
    return head + c.num(len(data), 2) + data


def requests(c):
    """(name, command, subcommand, body) for every command family."""
    d, w, u8 = c.device, c.num, lambda v: c.num(v, 1)
    r = [
        ("read_words_D", 0x0401, 0x0000, d("D", 100) + w(4, 2)),
        ("read_bits_M", 0x0401, 0x0001, d("M", 0) + w(8, 2)),
        ("read_words_iqr_ZR", 0x0401, 0x0002, d("ZR", 10, True) + w(2, 2)),
        ("read_bits_iqr_X", 0x0401, 0x0003, d("X", 0x10, True) + w(3, 2)),
        ("read_words_W_hex", 0x0401, 0x0000, d("W", 0x1F) + w(1, 2)),
        ("read_words_SD", 0x0401, 0x0000, d("SD", 0) + w(16, 2)),
        ("read_words_TN", 0x0401, 0x0000, d("TN", 0) + w(2, 2)),
        ("write_words_D", 0x1401, 0x0000, d("D", 0) + w(3, 2) + w(0x1234, 2) + w(0xABCD, 2) + w(7, 2)),
        ("write_bits_M", 0x1401, 0x0001, d("M", 10) + w(5, 2) + c.bits([1, 0, 1, 1, 0])),
        ("write_words_iqr_R", 0x1401, 0x0002, d("R", 5, True) + w(1, 2) + w(42, 2)),
        ("write_bits_iqr_Y", 0x1401, 0x0003, d("Y", 0, True) + w(2, 2) + c.bits([1, 1])),
        ("write_words_past_end", 0x1401, 0x0000, d("D", 0xFFFFFE if not c.ascii else 999998) + w(4, 2) + w(1, 2) * 4),
        ("read_random", 0x0403, 0x0000, u8(2) + u8(1) + d("D", 0) + d("W", 0x10) + d("D", 200)),
        ("read_random_iqr", 0x0403, 0x0002, u8(1) + u8(1) + d("D", 1, True) + d("ZR", 2, True)),
        ("write_random_words", 0x1402, 0x0000, u8(1) + u8(1) + d("D", 5) + w(0x55AA, 2) + d("D", 10) + w(0x12345678, 4)),
        ("write_random_bits", 0x1402, 0x0001, u8(2) + d("M", 1) + u8(1) + d("Y", 0x2F) + u8(0)),
        ("write_random_words_iqr", 0x1402, 0x0002, u8(1) + u8(0) + d("SD", 0, True) + w(1, 2)),
        ("read_block", 0x0406, 0x0000, u8(1) + u8(1) + d("D", 0) + w(2, 2) + d("M", 16) + w(1, 2)),
        ("write_block", 0x1406, 0x0000, u8(1) + u8(1) + d("D", 0) + w(2, 2) + w(1, 2) + w(2, 2) + d("M", 0) + w(1, 2) + w(0x8001, 2)),
        ("write_block_iqr", 0x1406, 0x0002, u8(1) + u8(0) + d("W", 0, True) + w(1, 2) + w(9, 2)),
        ("entry_monitor", 0x0801, 0x0000, u8(2) + u8(1) + d("D", 0) + d("M", 0) + d("D", 100)),
        ("execute_monitor", 0x0802, 0x0000, b""),
        ("read_type_name", 0x0101, 0x0000, b""),
        ("loopback", 0x0619, 0x0000, w(5, 2) + b"ABCDE"),
        ("memory_read", 0x0613, 0x0000, w(0, 4) + w(4, 2)),
        ("memory_write", 0x1613, 0x0000, w(0, 4) + w(2, 2) + w(1, 2) + w(2, 2)),
        ("extend_unit_read", 0x0601, 0x0000, w(0, 4) + w(4, 2) + w(0x03E0, 2)),
        ("extend_unit_write", 0x1601, 0x0000, w(0, 4) + w(2, 2) + w(0x03E0, 2) + (b"\x01\x02" if not c.ascii else b"0102")),
        ("remote_run", 0x1001, 0x0000, w(1, 2) + u8(0) + u8(0)),
        ("remote_run_forced_clear", 0x1001, 0x0000, w(3, 2) + u8(2) + u8(0)),
        ("remote_stop", 0x1002, 0x0000, w(1, 2)),
        ("remote_pause", 0x1003, 0x0000, w(1, 2)),
        ("remote_latch_clear", 0x1005, 0x0000, w(1, 2)),
        ("remote_reset", 0x1006, 0x0000, w(1, 2)),
        ("clear_error", 0x1617, 0x0000, b""),
        ("password_unlock", 0x1630, 0x0000, w(4, 2) + b"1234"),
        ("password_lock", 0x1631, 0x0000, w(4, 2) + b"1234"),
        ("unknown_command", 0x7777, 0x0000, b""),
    ]
    # The extended forms (008x): a plain device, J1\W and U3E0\G in binary.
    if c.ascii:
        ext_q = b"00" + b"0000" + b"000" + b"D*" + b"000100" + b"000"
        ext_j = b"00" + b"J001" + b"000" + b"W*" + b"000010" + b"000"
        ext_u = b"00" + b"U3E0" + b"000" + b"G*" + b"000000" + b"000"
        ext_z = b"00" + b"0000" + b"000" + b"D*" + b"000000" + b"Z01"
    else:
        ext_q = w(0, 2) + d("D", 100) + w(0, 2) + w(0, 2) + u8(0)
        ext_j = w(0, 2) + d("W", 0x10) + w(0, 2) + w(1, 2) + u8(0xF9)
        ext_u = w(0, 2) + (0).to_bytes(3, "little") + bytes([0xAB]) + w(0, 2) + w(0x03E0, 2) + u8(0xFA)
        ext_z = w(0x4001, 2) + d("D", 0) + w(0, 2) + w(0, 2) + u8(0)
    r += [
        ("ext_read_words", 0x0401, 0x0080, ext_q + w(2, 2)),
        ("ext_read_link_direct", 0x0401, 0x0080, ext_j + w(1, 2)),
        ("ext_read_cpu_buffer", 0x0401, 0x0080, ext_u + w(1, 2)),
        ("ext_read_index", 0x0401, 0x0080, ext_z + w(1, 2)),
        ("ext_write_words", 0x1401, 0x0080, ext_q + w(1, 2) + w(5, 2)),
        ("ext_read_random", 0x0403, 0x0080, u8(1) + u8(0) + ext_q),
    ]
    return r


def write(target, name, data):
    path = CORPUS / target / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data)


def engine_and_prefix_seeds():
    # Profiles are indexed in config::builtin_profile_names() order (sorted file names).
    profiles = sorted(p.stem for p in (REPO / "config" / "profiles").glob("*.json"))
    r08 = profiles.index("R08CPU")
    q26 = profiles.index("Q26UDEHCPU")
    for shape, (ascii, e4) in {"3e_bin": (False, False), "4e_bin": (False, True),
                               "3e_ascii": (True, False), "4e_ascii": (True, True)}.items():
        c = Codec(ascii)
        reqs = requests(c)
        for i, (name, cmd, sub, body) in enumerate(reqs):
            f = frame(c, e4, cmd, sub, body)
            # Mostly R08CPU, some Q26UDEHCPU (Q-series rules); policy 2 = auto,
            # writes (1xxx) with the snapshot compare (bit 3).
            profile = q26 if i % 4 == 3 else r08
            write("fuzz_engine", f"{shape}_{name}", bytes([profile, 0x0A if cmd >> 12 == 1 else 2]) + f)
            # The prefix target: bit 0 request, policy auto (bits 1-2 = 2).
            write("fuzz_frame_prefix", f"{shape}_{name}", bytes([0x04]) + f)
        # Several frames on one connection: write, read back, monitor.
        stream = b"".join(frame(c, e4, cmd, sub, body) for name, cmd, sub, body in reqs
                          if name in ("write_words_D", "read_words_D", "entry_monitor", "execute_monitor"))
        write("fuzz_engine", f"{shape}_stream", bytes([r08, 6]) + stream)   # 6: auto + CPU No.2
        write("fuzz_engine", f"{shape}_cpu2", bytes([r08, 6]) +
              frame(c, e4, 0x0401, 0, c.device("D", 0) + c.num(1, 2), route=(0, 0xFF, 0x03E1, 0)))
        write("fuzz_engine", f"{shape}_other_route", bytes([q26, 2]) +
              frame(c, e4, 0x0401, 0, c.device("D", 0) + c.num(1, 2), route=(1, 2, 0x03FF, 0)))
        # A response, for the prefix target's response direction.
        resp = (c.num(0xD4 if e4 else 0xD0, 1) + c.num(0, 1) + (c.num(0x1234, 2) + c.num(0, 2) if e4 else b"") +
                c.num(0, 1) + c.num(0xFF, 1) + c.num(0x03FF, 2) + c.num(0, 1))
        payload = c.num(0, 2) + c.num(0x1234, 2)
        write("fuzz_frame_prefix", f"{shape}_response", bytes([0x05]) + resp + c.num(len(payload), 2) + payload)
    # Every profile once, with a binary read and an ASCII one on a policy each
    # (bit 3: with the full memory snapshot compare).
    for i, p in enumerate(profiles):
        write("fuzz_engine", f"profile_{p}_bin", bytes([i, 0x08]) + frame(Codec(False), False, 0x0401, 0, Codec(False).device("D", 0) + Codec(False).num(2, 2)))
        write("fuzz_engine", f"profile_{p}_ascii", bytes([i, 0x09]) + frame(Codec(True), False, 0x0101, 0, b""))


def field_seeds():
    # [flags][n ops][ops][data]: ops 3 = Q device, 4 = iQ-R device, 1 = u16, 0x28 = 2 words, 0x17 = 3 bits.
    b, a = Codec(False), Codec(True)
    write("fuzz_fields", "bin_q_device", bytes([0, 3, 3, 1, 10]) + b.device("D", 100) + b.num(4, 2))
    write("fuzz_fields", "ascii_q_device", bytes([1, 3, 3, 1, 10]) + a.device("W", 0x1F) + a.num(4, 2))
    write("fuzz_fields", "ascii_zr_hex", bytes([3, 2, 3, 10]) + a.device("ZR", 0x1F))
    write("fuzz_fields", "bin_iqr_words", bytes([0, 3, 4, 0x28, 10]) + b.device("ZR", 5, True) + b.num(1, 2) + b.num(2, 2))
    write("fuzz_fields", "ascii_iqr_bits", bytes([1, 3, 4, 0x17, 10]) + a.device("M", 5, True) + b"101")
    write("fuzz_fields", "bin_bits", bytes([0, 2, 0x17, 10]) + b.bits([1, 0, 1]))
    write("fuzz_fields", "bin_ext", bytes([0, 2, 5, 10]) + b.num(0, 2) + b.device("W", 0x10) + b.num(0, 2) + b.num(1, 2) + b"\xF9")
    write("fuzz_fields", "ascii_ext", bytes([1, 2, 5, 10]) + b"00J001000W*000010000")
    write("fuzz_fields", "ascii_ext_iqr", bytes([1, 2, 6, 10]) + b"00U3E00000G***00000000000000")
    write("fuzz_fields", "raw", bytes([1, 3, 1, 0x19, 10]) + a.num(5, 2) + b"HELLO")


def json_seeds():
    for p in sorted((REPO / "scenarios" / "examples").glob("*.json")):
        write("fuzz_scenario", p.name, p.read_bytes())
    mistakes = json.loads((REPO / "tests" / "data" / "scenario_mistakes.json").read_text())
    for i, m in enumerate(mistakes):
        text = m["text"] if "text" in m else json.dumps(m["doc"], indent=1)
        write("fuzz_scenario", f"mistake_{i:02d}.json", text.encode())
    for p in sorted((REPO / "config" / "profiles").glob("*.json")):
        write("fuzz_config", "profile_" + p.name, p.read_bytes())
    # Server configurations: the JSON examples of docs/configuration.md.
    doc = (REPO / "docs" / "configuration.md").read_text()
    for i, block in enumerate(re.findall(r"```json\n(.*?)```", doc, re.S)):
        write("fuzz_config", f"doc_{i:02d}.json", block.encode())
    write("fuzz_config", "small.json", b'{"profile": "Q26UDEHCPU", "ports": [{"port": 0, "data_code": "ascii"}], '
          b'"device_sizes": {"D": 2048}, "devices": {"D100": [1, 2, 3]}}')
    write("fuzz_config", "cpu.json", b'{"cpu": {"switch": "STOP", "scan_time_ms": 5, "latch": {"D": [[0, 9], ["D100", "D199"]]}, '
          b'"timers": [{"device": "T0", "preset": 10}], "counters": [{"device": "C0", "preset": 3}], '
          b'"password": "1234", "password_lockout": {"attempts": 3, "seconds": 10}}}')


# fuzz_http: requests joined by NUL, each a method digit, the target, and
# after a newline the body (tests/fuzz/fuzz_http.cpp).
METHODS = {"GET": b"0", "PUT": b"1", "POST": b"2", "DELETE": b"3", "PATCH": b"4"}


def http(*requests):
    """(method, target[, body]) each; a body that is not a str is sent as JSON."""
    out = []
    for method, target, *body in requests:
        text = METHODS[method] + target.encode()
        if body:
            text += b"\n" + (body[0] if isinstance(body[0], str) else json.dumps(body[0])).encode()
        out.append(text)
    return b"\0".join(out)


def http_seeds():
    """Every route of docs/api.md with a body it takes, and mistakes of each kind.
    The station's areas hold 512 points (D0-D511; fuzz_http.cpp)."""
    fault = {"name": "refuse-d100", "faults": [{"id": "no-d100", "do": "end_code", "end_code": "C051",
                                                 "match": {"devices": "D100-D199"}}]}
    seeds = {
        "info": [("GET", "/api/info")],
        "devices_read": [("GET", "/api/devices/D100?count=3"), ("GET", "/api/devices/M0?count=8"),
                         ("GET", "/api/devices/M0?as=words"), ("GET", "/api/devices/LTN0?count=2"),
                         ("GET", "/api/devices/X1F?as=dwords&count=2")],
        "devices_write": [("PUT", "/api/devices/D100", {"values": [1, -1, 4660]}), ("GET", "/api/devices/D100?count=3")],
        "devices_write_bits": [("PUT", "/api/devices/X1F", {"values": [True, 0, 1]}),
                               ("PUT", "/api/devices/M0?as=words", {"values": [65535]})],
        "devices_write_dwords": [("PUT", "/api/devices/D200?as=dwords", {"values": [305419896, -1]}),
                                 ("PUT", "/api/devices/LTN0", {"values": [70000]}),
                                 ("PUT", "/api/devices/SD203", {"values": [2]})],
        "devices_string": [("PUT", "/api/devices/D300", {"string": "HELLO"}),
                           ("GET", "/api/devices/D300?as=string&count=10"),
                           ("PUT", "/api/devices/D310?as=string", '{"string": "\\u00e9\\u0000A"}')],
        "devices_refused": [("PUT", "/api/devices/D510", {"values": [1, 2, 3]}),
                            ("PUT", "/api/devices/D0", {"values": [1, 70000]}),
                            ("PUT", "/api/devices/D0", {"values": [1], "string": "x"}),
                            ("PUT", "/api/devices/D0?as=bits", {"values": [1]}),
                            ("PUT", "/api/devices/M0", {"string": "x"}),
                            ("PUT", "/api/devices/D0", {"string": "\u3042"}),
                            ("PUT", "/api/devices/D0", '{"values": [1,'),
                            ("PUT", "/api/devices/D0", {"values": [1.5]}),
                            ("PUT", "/api/devices/D0", {"value": 5})],
        "devices_errors": [("GET", "/api/devices/D511?count=2"), ("GET", "/api/devices/Q100"),
                           ("GET", "/api/devices/D0?cnt=2"), ("GET", "/api/devices/D0?count=0"),
                           ("GET", "/api/devices/D0?count=65537"), ("GET", "/api/devices/D0?count=x"),
                           ("GET", "/api/devices/D0?as=bytes"), ("GET", "/api/devices/G0"),
                           ("GET", "/api/devices/D0?count=%zz")],
        "buffer": [("GET", "/api/buffer"), ("PUT", "/api/buffer/U3/G100", {"values": [4660, 65535]}),
                   ("GET", "/api/buffer/U3/G100?count=2&as=dwords"), ("GET", "/api/buffer/U3E0/HG0?count=2"),
                   ("PUT", "/api/buffer/U3E1/G0?as=string", {"string": "AB"}),
                   ("PUT", "/api/buffer/station/G10", {"values": [7]}), ("GET", "/api/buffer/u03/G100")],
        "buffer_errors": [("GET", "/api/buffer/U5/G0"), ("GET", "/api/buffer/U3/HG0"),
                          ("GET", "/api/buffer/U3/G511?count=2"), ("GET", "/api/buffer/U3/D0"),
                          ("GET", "/api/buffer/U3/G0?as=bits"), ("PUT", "/api/buffer/U3/G511", {"values": [1, 2]})],
        "scenario_faults": [("POST", "/api/scenarios", fault), ("GET", "/api/scenarios"), ("GET", "/api/faults"),
                            ("PUT", "/api/faults/no-d100", {"enabled": False}),
                            ("PUT", "/api/faults/nope", {"enabled": False}),
                            ("PUT", "/api/faults/no-d100", {"enabled": "no"}),
                            ("POST", "/api/scenarios", fault),
                            ("DELETE", "/api/scenarios/refuse-d100"), ("DELETE", "/api/scenarios/refuse-d100")],
        # A fault without an id is named "<source>#<pointer>", percent-encoded in the path.
        "scenario_unnamed_fault": [("POST", "/api/scenarios", {"name": "x", "faults": [
                                       {"do": "end_code", "end_code": "C051", "match": {"command": "0401"}}]}),
                                   ("PUT", "/api/faults/request%20body%20(x)%23%2Ffaults%2F0", {"enabled": False}),
                                   ("DELETE", "/api/scenarios/x")],
        "scenario_errors": [("POST", "/api/scenarios", {"faults": []}), ("POST", "/api/scenarios", "[]"),
                            ("POST", "/api/scenarios", {"name": "d", "initial": {"devices": {"D600": 1}}}),
                            ("POST", "/api/scenarios", {"name": "p", "initial": {"password": "1234"}}),
                            ("DELETE", "/api/scenarios/none")],
        "state": [("GET", "/api/state"), ("PUT", "/api/state", {"switch": "STOP"}), ("GET", "/api/state"),
                  ("PUT", "/api/state", {"switch": "PAUSE"}), ("PUT", "/api/state", {"switch": "RUN", "x": 1}),
                  ("PUT", "/api/state", "[]"), ("PUT", "/api/state", {"switch": "RUN"})],
        "recording": [("GET", "/api/recording"), ("DELETE", "/api/recording"), ("POST", "/api/recording", {}),
                      ("POST", "/api/recording", {"path": "x.jsonl"})],
        "connections": [("GET", "/api/connections"), ("DELETE", "/api/connections/3"),
                        ("DELETE", "/api/connections/abc")],
        "events": [("GET", "/api/events"), ("GET", "/api/events?types=request,devices"),
                   ("GET", "/api/events?types=bogus")],
        "metrics": [("GET", "/metrics")],
        "static": [("GET", "/"), ("GET", "/index.html"), ("GET", "/app.js"), ("GET", "/style.css")],
        "routing": [("GET", "/api/device/D1"), ("DELETE", "/api/devices/D1"), ("PATCH", "/api/state", {}),
                    ("GET", "/api/%64evices/D1"), ("GET", "/api/devices/U3E0%5CG10"), ("GET", "/api%2Finfo"),
                    ("GET", "//api//info?"), ("GET", "/api/info?x"), ("GET", "/api/info%"),
                    ("GET", "/api/devices/D0?count=2&count=3&as=words&"), ("GET", "api/info")],
    }
    for name, requests in seeds.items():
        write("fuzz_http", name, http(*requests))
    # Every shipped scenario posted as the body, listed, then stopped.
    for p in sorted((REPO / "scenarios" / "examples").glob("*.json")):
        name = json.loads(p.read_text())["name"]
        write("fuzz_http", "scenario_" + p.stem, http(("POST", "/api/scenarios", p.read_text()), ("GET", "/api/scenarios"),
                                                    ("GET", "/api/faults"), ("GET", "/metrics"),
                                                    ("DELETE", "/api/scenarios/" + name)))


if __name__ == "__main__":
    if CORPUS.exists():
        shutil.rmtree(CORPUS)
    engine_and_prefix_seeds()
    field_seeds()
    json_seeds()
    http_seeds()
    for d in sorted(CORPUS.iterdir()):
        print(d.name, len(list(d.iterdir())))
