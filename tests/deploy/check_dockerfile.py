#!/usr/bin/env python3
"""The Dockerfile and deploy/image/ describe one image (no Docker needed).

- deploy/image/runtime-packages.txt is exactly the set of Debian packages that
  own the shared libraries `ldd SLMP_SIM_BINARY` lists (dpkg -S): a library
  the binary gained, or a package it no longer needs, fails here;
- the Dockerfile's final stage installs packages only from that file;
- it creates the user with the same useradd arguments as
  deploy/image/base-rootfs.sh, and USER is that uid:gid;
- it copies the files deploy/image/build.sh puts in the image, to the same
  places;
- EXPOSE is the default configuration's ports (deploy/image/config.json) and
  its HTTP port; HEALTHCHECK runs slmp-sim-healthcheck against /healthz;
  ENTRYPOINT and CMD start slmp-sim with that configuration.

(That the image build.sh makes has the Dockerfile's entrypoint, command, user,
ports and labels is checked on the built image by check_image.py.)
Skipped (exit 77) without ldd or dpkg-query (a host that is not Debian).
Usage: check_dockerfile.py SLMP_SIM_BINARY REPO_ROOT
"""
import json
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys

import dockerfile
from report import Report, skip_test

binary, repo = sys.argv[1], pathlib.Path(sys.argv[2])
for tool, package in (("ldd", "libc-bin"), ("dpkg-query", "dpkg")):
    if shutil.which(tool) is None:
        skip_test(f"{tool} is not installed ({package}): the runtime packages are Debian's")
report = Report()
image_dir = repo / "deploy/image"


def listed_packages():
    lines = (image_dir / "runtime-packages.txt").read_text().splitlines()
    return {line.strip() for line in lines if line.strip() and not line.lstrip().startswith("#")}


def owner(library):
    """The package that installed a library; tries the path as given and as resolved (merged /usr)."""
    real = os.path.realpath(library)
    for path in (library, real, re.sub(r"^/lib", "/usr/lib", library), re.sub(r"^/usr/lib", "/lib", real)):
        found = subprocess.run(["dpkg-query", "-S", path], capture_output=True, text=True)
        if found.returncode == 0:
            return found.stdout.split(":", 1)[0].strip()
    return None


def ldd_packages():
    out = subprocess.run(["ldd", binary], capture_output=True, text=True, check=True).stdout
    libraries = re.findall(r"=> (/\S+)", out) + re.findall(r"^\s*(/\S+) \(", out, re.MULTILINE)
    packages = set()
    for library in libraries:
        package = owner(library)
        if report.check(package is not None, f"no Debian package owns {library} (ldd {binary})"):
            packages.add(package)
    return packages


def useradd_words(command_text):
    """The words of the useradd command in a shell text, up to the next && or end."""
    words = shlex.split(command_text)
    start = words.index("useradd")
    end = words.index("&&", start) if "&&" in words[start:] else len(words)
    return words[start:end]


report.equal(listed_packages(), ldd_packages(), "deploy/image/runtime-packages.txt vs the owners of ldd's libraries")

final = dockerfile.stages((repo / "Dockerfile").read_text())[-1]
runs = dockerfile.all_of(final, "RUN")
copies = [args.split() for args in dockerfile.all_of(final, "COPY")]

# Packages: only from the list.
report.check(["deploy/image/runtime-packages.txt", "/tmp/runtime-packages.txt"] in copies,
             "the final stage copies deploy/image/runtime-packages.txt to /tmp/runtime-packages.txt")
installs = [run for run in runs if "apt-get install" in run]
report.equal(len(installs), 1, "apt-get install commands in the final stage")
for run in installs:
    after = run.split("apt-get install", 1)[1].split("&&", 1)[0].split()
    report.check(all(word.startswith("-") for word in after),
                 f"apt-get install in the final stage names no package itself: {after}")
    report.check("/tmp/runtime-packages.txt" in run.split("apt-get install", 1)[0],
                 "apt-get install reads its packages from /tmp/runtime-packages.txt")

# The user.
script = (image_dir / "base-rootfs.sh").read_text().replace("\\\n", " ")
uid = re.search(r"^uid=(\d+)$", script, re.MULTILINE).group(1)
script_line = next(line for line in script.splitlines() if "useradd" in line)
script_words = useradd_words(script_line.replace('"$uid"', uid))
docker_words = useradd_words(next(run for run in runs if "useradd" in run))
report.equal(docker_words, script_words, "useradd in the Dockerfile vs deploy/image/base-rootfs.sh")
report.equal(dockerfile.one_of(final, "USER"), f"{uid}:{uid}", "USER")

# The files, where build.sh puts them.
build_sh = (image_dir / "build.sh").read_text()
for source, target in (("deploy/image/healthcheck.sh", "/usr/local/bin/slmp-sim-healthcheck"),
                       ("deploy/image/config.json", "/etc/slmp-sim/config.json"),
                       ("examples/", "/usr/share/slmp-sim/examples/")):
    report.check([source, target] in copies, f"the Dockerfile copies {source} to {target}")
    report.check(target.rstrip("/") in build_sh, f"deploy/image/build.sh puts {target} in the image too")
report.check(any(c[-1] == "/usr/local/bin/slmp-sim" and c[0].startswith("--from=") for c in copies),
             "the Dockerfile copies the built slmp-sim to /usr/local/bin/slmp-sim")

# Ports, health check, entrypoint.
config = json.loads((image_dir / "config.json").read_text())
ports = {f"{p['port']}/{p['transport']}" for p in config["ports"]} | {f"{config['http']['port']}/tcp"}
report.equal(dockerfile.exposed_ports(final), ports, "EXPOSE vs deploy/image/config.json")
health = dockerfile.one_of(final, "HEALTHCHECK") or ""
report.check(re.search(r'CMD \["slmp-sim-healthcheck", "/healthz"\]', health) is not None,
             f"HEALTHCHECK runs slmp-sim-healthcheck /healthz: {health!r}")
report.equal(dockerfile.exec_form(dockerfile.one_of(final, "ENTRYPOINT")), ["slmp-sim"], "ENTRYPOINT")
report.equal(dockerfile.exec_form(dockerfile.one_of(final, "CMD")), ["--config", "/etc/slmp-sim/config.json"], "CMD")
report.finish()
