#!/usr/bin/env python3
"""The container image, built and run here without a container daemon.

1. deploy/image/build.sh builds the OCI layout (and loads it into podman when
   podman is installed).
2. The image's configuration is the Dockerfile's final stage: entrypoint,
   command, user, working directory, ports, stop signal, labels.
3. umoci unpacks the image; in its root filesystem (chroot), as the image's
   user, with its environment and working directory, as a runtime would:
   --check-config of the default configuration and the bundled plant examples
   (exit 0) and of a broken one (exit 2, one line); a plant of 3 stations with
   --ready-file: a byte-exact 3E read from one station, GET /healthz and
   /readyz, slmp-sim-healthcheck (the Dockerfile's HEALTHCHECK) against both
   and against a missing path, then SIGTERM → exit 0.
4. podman: the loaded image is the layout's (same configuration digest), and
   `podman run` of it — that part is skipped, with the runtime's message, where
   the sandbox refuses to run containers.

Skipped (exit 77) without root, debootstrap, umoci or chroot.
Usage: check_image.py SLMP_SIM_BINARY REPO_ROOT OUTPUT_DIR
"""
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import time

import dockerfile
from report import Report, skip_test
from sim_process import SimProcess
from wire import http_get, read_words_3e, slmp_exchange

binary, repo, output = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])

if os.geteuid() != 0:
    skip_test("building the image needs root (debootstrap creates device nodes; the checks chroot)")
for tool, package in (("debootstrap", "debootstrap"), ("umoci", "umoci"), ("chroot", "coreutils")):
    if shutil.which(tool) is None:
        skip_test(f"{tool} is not installed (apt-get install {package}, or run scripts/setup.sh)")

report = Report()
version = re.search(r"project\(slmp-sim VERSION ([0-9.]+)", (repo / "CMakeLists.txt").read_text()).group(1)
layout = output / "slmp-sim"


def blob(digest):
    return json.loads((layout / "blobs" / "sha256" / digest.split(":", 1)[1]).read_text())


# 1. Build.
since = time.monotonic()
built = subprocess.run([repo / "deploy/image/build.sh", "--binary", binary, "--output", output])
report.timing("deploy/image/build.sh", since)
if built.returncode != 0:
    print(f"FAIL: deploy/image/build.sh exited with {built.returncode}")
    sys.exit(1)

# 2. The image's configuration against the Dockerfile's final stage.
index = json.loads((layout / "index.json").read_text())
report.equal([m["annotations"]["org.opencontainers.image.ref.name"] for m in index["manifests"]], [version],
             "the layout's tags")
manifest = blob(index["manifests"][0]["digest"])
config_digest = manifest["config"]["digest"]
image = blob(config_digest)["config"]
final = dockerfile.stages((repo / "Dockerfile").read_text())[-1]
report.equal(image["Entrypoint"], dockerfile.exec_form(dockerfile.one_of(final, "ENTRYPOINT")), "Entrypoint vs Dockerfile")
report.equal(image["Cmd"], dockerfile.exec_form(dockerfile.one_of(final, "CMD")), "Cmd vs Dockerfile")
report.equal(image["User"], dockerfile.one_of(final, "USER"), "User vs Dockerfile")
report.equal(image["WorkingDir"], dockerfile.one_of(final, "WORKDIR"), "WorkingDir vs Dockerfile")
report.equal(set(image["ExposedPorts"]), dockerfile.exposed_ports(final), "ExposedPorts vs Dockerfile")
report.equal(image.get("StopSignal"), dockerfile.one_of(final, "STOPSIGNAL"), "StopSignal vs Dockerfile")
for key, value in dockerfile.labels(final).items():
    report.equal(image["Labels"].get(key), value, f"label {key} vs Dockerfile")
report.equal(image["Labels"].get("org.opencontainers.image.version"), version, "label version")

# 3. The unpacked root filesystem, run as a runtime would run the image.
bundle = output / "test-bundle"
shutil.rmtree(bundle, ignore_errors=True)
since = time.monotonic()
subprocess.run(["umoci", "unpack", "--image", f"{layout}:{version}", bundle], check=True)
report.timing("umoci unpack", since)
rootfs = bundle / "rootfs"
report.equal((rootfs / "etc/slmp-sim/config.json").read_bytes(), (repo / "deploy/image/config.json").read_bytes(),
             "/etc/slmp-sim/config.json")
report.equal((rootfs / "usr/local/bin/slmp-sim-healthcheck").read_bytes(),
             (repo / "deploy/image/healthcheck.sh").read_bytes(), "/usr/local/bin/slmp-sim-healthcheck")
user, group = image["User"].split(":")
report.check(f"slmp-sim:x:{user}:{group}:" in (rootfs / "etc/passwd").read_text(), f"/etc/passwd has slmp-sim as {user}:{group}")


def in_image(*args):
    """A command line running args in the image as its user, environment and working directory."""
    return ["chroot", f"--userspec={image['User']}", str(rootfs), "/usr/bin/env", "-i", "-C", image["WorkingDir"],
            *image["Env"], *args]


checks = ["/etc/slmp-sim/config.json"] + sorted(
    "/" + str(p.relative_to(rootfs)) for p in (rootfs / "usr/share/slmp-sim/examples/plants").glob("*.json"))
print("--check-config in the image:", " ".join(checks))
for config in checks:
    run = subprocess.run(in_image(*image["Entrypoint"], "--check-config", config), capture_output=True, text=True)
    report.check(run.returncode == 0, f"--check-config {config} in the image: exit {run.returncode}: {run.stderr.strip()}")

work = rootfs / "tmp/deploy-test"
work.mkdir()
os.chown(work, int(user), int(group))
(work / "broken.json").write_text('{"profile": "R08CPU", "prots": []}\n')
run = subprocess.run(in_image(*image["Entrypoint"], "--check-config", "/tmp/deploy-test/broken.json"),
                     capture_output=True, text=True)
report.equal(run.returncode, 2, "--check-config of a broken configuration: exit code")
report.check(run.stderr.startswith("slmp-sim: error: /tmp/deploy-test/broken.json: /prots") and run.stderr.count("\n") == 1,
             f"--check-config of a broken configuration: one line naming the key, got {run.stderr!r}")

# D100-D101 of every press hold 1234 5678 (hex); every port is any free one on loopback.
(work / "plant.json").write_text(json.dumps({
    "http": {"port": 0, "bind": "127.0.0.1"},
    "stations": [{"template": {"profile": "R08CPU", "devices": {"D100": [0x1234, 0x5678]}}, "count": 3,
                  "name": "press-{i}", "bind": "127.0.0.1", "tcp_port": 0}]}))
since = time.monotonic()
sim = SimProcess(in_image(*image["Entrypoint"], "--config", "/tmp/deploy-test/plant.json",
                          "--ready-file", "/tmp/deploy-test/ready.json", "--threads", "2"),
                 str(work / "ready.json"), str(output / "test-plant.log"))
try:
    ready = sim.wait_ready()
    report.timing("start of a 3-station plant in the image until its ready file", since)
    report.equal([s["name"] for s in ready["stations"]], ["press-1", "press-2", "press-3"], "the ready file's stations")
    press2 = ready["stations"][1]["tcp"][0]
    answer = slmp_exchange("127.0.0.1", press2, read_words_3e(0xA8, 100, 2), 15)
    report.equal(answer.hex(" "), "d0 00 00 ff ff 03 00 06 00 00 00 34 12 78 56", "3E read of D100-D101 from press-2")
    http = ready["http"]
    report.equal(http_get("127.0.0.1", http, "/healthz"), (200, b'{"status":"ok"}\n'), "GET /healthz")
    status, body = http_get("127.0.0.1", http, "/readyz")
    report.equal((status, json.loads(body)), (200, {"ready": True, "stations": 3}), "GET /readyz")
    for path, expected in (("/healthz", 0), ("/readyz", 0), ("/no-such-path", 1)):
        check = subprocess.run(in_image("slmp-sim-healthcheck", path, str(http)), capture_output=True, text=True)
        report.equal(check.returncode, expected, f"slmp-sim-healthcheck {path} (stderr {check.stderr.strip()!r})")
    since = time.monotonic()
    report.equal(sim.stop(), 0, "exit code after SIGTERM")
    report.timing("SIGTERM until exit", since)
except Exception as e:  # the log says why; the process must not outlive the test
    sim.kill()
    report.check(False, f"the plant in the image: {e}")
shutil.rmtree(bundle, ignore_errors=True)

# 4. podman.
if shutil.which("podman") is None:
    report.skip_part("podman load and podman run", "podman is not installed (apt-get install podman)")
else:
    name = f"localhost/slmp-sim:{version}"
    loaded = subprocess.run(["podman", "image", "inspect", "--format", "{{.Id}}", name], capture_output=True, text=True)
    report.equal(loaded.stdout.strip(), config_digest.split(":", 1)[1], f"podman's {name} is the built image")
    run = subprocess.run(["podman", "run", "--rm", "--network", "none", name, "--check-config", "/etc/slmp-sim/config.json"],
                         capture_output=True, text=True)
    message = (run.stdout + run.stderr).strip()
    refused = re.search(r"\b(crun|runc)\b.*(Operation not permitted|permission denied)", message, re.IGNORECASE)
    if run.returncode in (125, 126) and refused:
        report.skip_part("podman run", f"the container runtime is refused here: {message}")
    else:
        report.check(run.returncode == 0 and "configuration OK" in message,
                     f"podman run {name} --check-config: exit {run.returncode}: {message}")

report.finish()
