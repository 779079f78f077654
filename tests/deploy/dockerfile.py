"""A Dockerfile read as stages of (INSTRUCTION, arguments): enough to compare
the Dockerfile with deploy/image/ without Docker (continuation lines joined,
comments dropped, JSON-form arguments decoded)."""
import json
import re


def instructions(text):
    """[(INSTRUCTION, raw argument text)] in file order."""
    out, pending = [], ""
    for line in text.splitlines():
        if not pending and (not line.strip() or line.lstrip().startswith("#")):
            continue
        if pending and line.lstrip().startswith("#"):
            continue  # a comment inside a continued instruction
        if line.rstrip().endswith("\\"):
            pending += line.rstrip()[:-1] + " "
            continue
        full = pending + line
        pending = ""
        word, _, rest = full.strip().partition(" ")
        out.append((word.upper(), rest.strip()))
    return out


def stages(text):
    """Instructions grouped by FROM: [[("FROM", ...), ...], ...]."""
    result = []
    for instruction in instructions(text):
        if instruction[0] == "FROM":
            result.append([])
        if result:
            result[-1].append(instruction)
    return result


def exec_form(arguments):
    """["a", "b"] → ['a', 'b']; a shell form → ['/bin/sh', '-c', text]."""
    if arguments.startswith("["):
        return json.loads(arguments)
    return ["/bin/sh", "-c", arguments]


def all_of(stage, name):
    return [args for word, args in stage if word == name]


def one_of(stage, name):
    found = all_of(stage, name)
    return found[-1] if found else None


def exposed_ports(stage):
    """{'5000/tcp', ...} of every EXPOSE (a bare port is TCP, as Docker reads it)."""
    ports = set()
    for args in all_of(stage, "EXPOSE"):
        for port in args.split():
            ports.add(port if "/" in port else port + "/tcp")
    return ports


def labels(stage):
    """LABEL key="value" ... pairs of the stage."""
    found = {}
    for args in all_of(stage, "LABEL"):
        for key, quoted, bare in re.findall(r'([\w.-]+)=(?:"((?:[^"\\]|\\.)*)"|(\S+))', args):
            found[key] = quoted if quoted or not bare else bare
    return found
