"""The two conversations the deploy tests have with slmp-sim: one HTTP GET,
one SLMP request over TCP; both byte-level, standard library only."""
import socket

TIMEOUT_S = 10


def http_get(host, port, path):
    """(status, body bytes) of GET path, HTTP/1.0 so the server closes after the answer."""
    with socket.create_connection((host, port), timeout=TIMEOUT_S) as s:
        s.sendall(f"GET {path} HTTP/1.0\r\nHost: {host}\r\n\r\n".encode())
        data = b""
        while chunk := s.recv(65536):
            data += chunk
    head, _, body = data.partition(b"\r\n\r\n")
    status = int(head.split(b" ", 2)[1])
    return status, body


def read_words_3e(device_code, head, count):
    """A binary 3E Device Read (0401/0000, word units) request for `count` words from `head`."""
    body = (bytes([0x10, 0x00])                        # monitoring timer
            + bytes([0x01, 0x04, 0x00, 0x00])          # command 0401, subcommand 0000
            + head.to_bytes(3, "little") + bytes([device_code])
            + count.to_bytes(2, "little"))
    return (bytes([0x50, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00])
            + len(body).to_bytes(2, "little") + body)


def slmp_exchange(host, port, request, response_length):
    """Sends one request over TCP and returns exactly response_length bytes of answer."""
    with socket.create_connection((host, port), timeout=TIMEOUT_S) as s:
        s.sendall(request)
        data = b""
        while len(data) < response_length:
            chunk = s.recv(response_length - len(data))
            if not chunk:
                break
            data += chunk
    return data
