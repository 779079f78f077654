#!/usr/bin/env python3
"""The Kubernetes manifests (deploy/k8s/*.yaml) against the image and the binary.

For each file:
- it parses (python3-yaml) into exactly a ConfigMap, a Deployment and a Service;
- the Deployment runs one replica of the slmp-sim image as the image's user
  (runAsNonRoot, runAsUser 10001, no privilege escalation), with CPU and memory
  requests and limits; its --config file is a key of the ConfigMap, mounted
  where the argument says; the Service selects the Deployment's pods and each
  of its target ports is a container port;
- every configuration in the ConfigMap passes `slmp-sim --check-config`;
- Prometheus scrape annotations name /metrics on the HTTP port;
- the liveness probe is GET /healthz and the readiness probe GET /readyz on the
  container port that is the configuration's HTTP port;
- the configuration is started unchanged in a network namespace of its own (as
  in a pod: its ports, 0.0.0.0, nothing reachable from outside): the ports its
  ready file lists plus the HTTP port are exactly the container ports, and the
  probes' paths answer 200 there (slmp-sim-healthcheck run in the namespace);
  SIGTERM → exit 0.

Skipped (exit 77) without python3-yaml; the namespace part needs root,
unshare, nsenter and ip (iproute2), and the test is skipped without them.
Usage: check_k8s.py SLMP_SIM_BINARY REPO_ROOT BUILD_DIR
"""
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

from report import Report, skip_test
from sim_process import SimProcess

try:
    import yaml
except ImportError:
    skip_test("python3-yaml is not installed (apt-get install python3-yaml, or run scripts/setup.sh)")

binary, repo, build = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
IMAGE_USER = 10001        # the image's user slmp-sim (Dockerfile USER, deploy/image/base-rootfs.sh)
DEFAULT_HTTP_PORT = 8080  # slmp-sim's --http-port default (docs/configuration.md)
report = Report()

pod_tools = [t for t in ("unshare", "nsenter", "ip") if shutil.which(t) is None]
if os.geteuid() != 0 or pod_tools:
    missing = "root" if os.geteuid() != 0 else ", ".join(pod_tools) + " (util-linux, iproute2)"
    skip_test(f"starting the manifests' configurations in a network namespace needs {missing}")


def container_port(container, port):
    """The containerPort entry a probe's or Service's port (a name or a number) means."""
    for entry in container.get("ports", []):
        if port in (entry.get("name"), entry["containerPort"]):
            return entry
    return None


def served_ports(ready):
    """{(port, 'TCP'|'UDP')} of every station in a ready file (one station or a plant)."""
    stations = ready.get("stations", [ready])
    return {(p, proto.upper()) for s in stations for proto in ("tcp", "udp") for p in s.get(proto, [])}


def start_in_namespace(config_file, work, name):
    """The configuration started as is, in a new network namespace with only loopback up."""
    ready = work / f"{name}.ready.json"
    command = ["unshare", "--net", "--", "sh", "-c", 'ip link set lo up && exec "$0" "$@"',
               binary, "--config", str(config_file), "--ready-file", str(ready)]
    return SimProcess(command, str(ready), str(work / f"{name}.log"))


def check_manifest(path, work):
    name = path.stem
    docs = [d for d in yaml.safe_load_all(path.read_text()) if d]
    kinds = sorted(d["kind"] for d in docs)
    if not report.equal(kinds, ["ConfigMap", "Deployment", "Service"], f"{name}: kinds"):
        return
    config_map, deployment, service = (next(d for d in docs if d["kind"] == k) for k in ("ConfigMap", "Deployment", "Service"))

    spec = deployment["spec"]
    pod = spec["template"]["spec"]
    pod_labels = spec["template"]["metadata"]["labels"]
    report.equal(spec.get("replicas"), 1, f"{name}: replicas")
    report.check(spec["selector"]["matchLabels"].items() <= pod_labels.items(), f"{name}: the Deployment selects its pods")
    report.check(service["spec"]["selector"].items() <= pod_labels.items(), f"{name}: the Service selects the pods")
    report.equal(len(pod["containers"]), 1, f"{name}: containers")
    container = pod["containers"][0]
    report.check("slmp-sim" in container["image"], f"{name}: image {container['image']} is slmp-sim")
    security = pod.get("securityContext", {})
    report.equal(security.get("runAsNonRoot"), True, f"{name}: runAsNonRoot")
    report.equal(security.get("runAsUser"), IMAGE_USER, f"{name}: runAsUser (the image's user)")
    report.equal(container.get("securityContext", {}).get("allowPrivilegeEscalation"), False,
                 f"{name}: allowPrivilegeEscalation")
    resources = container.get("resources", {})
    for kind in ("requests", "limits"):
        report.equal(sorted(resources.get(kind, {})), ["cpu", "memory"], f"{name}: resources.{kind}")

    # Every configuration in the ConfigMap is one slmp-sim accepts.
    for key, text in config_map["data"].items():
        if key.endswith(".json"):
            (work / key).write_text(text)
            run = subprocess.run([binary, "--check-config", str(work / key)], capture_output=True, text=True)
            report.check(run.returncode == 0, f"{name}: --check-config {key}: exit {run.returncode}: {run.stderr.strip()}")

    # The container's --config is the ConfigMap's, mounted where the argument says.
    args = container.get("args", [])
    if not report.check(len(args) >= 2 and args[0] == "--config", f"{name}: args start with --config FILE: {args}"):
        return
    config_path = pathlib.PurePosixPath(args[1])
    volumes = {v["name"]: v for v in pod.get("volumes", [])}
    mounts = [m for m in container.get("volumeMounts", [])
              if pathlib.PurePosixPath(m["mountPath"]) == config_path.parent
              and volumes.get(m["name"], {}).get("configMap", {}).get("name") == config_map["metadata"]["name"]]
    report.check(len(mounts) == 1, f"{name}: {config_path.parent} is the ConfigMap {config_map['metadata']['name']} mounted")
    if not report.check(config_path.name in config_map["data"], f"{name}: the ConfigMap has {config_path.name}"):
        return
    config = json.loads(config_map["data"][config_path.name])

    http_port = config.get("http", {}).get("port", DEFAULT_HTTP_PORT)
    for probe, path in (("livenessProbe", "/healthz"), ("readinessProbe", "/readyz")):
        get = container.get(probe, {}).get("httpGet", {})
        report.equal(get.get("path"), path, f"{name}: {probe} path")
        entry = container_port(container, get.get("port"))
        report.check(entry is not None and entry["containerPort"] == http_port and entry.get("protocol", "TCP") == "TCP",
                     f"{name}: {probe} port {get.get('port')} is the HTTP port {http_port}")
    # Prometheus scrapes /metrics on the HTTP port.
    annotations = deployment["spec"]["template"]["metadata"].get("annotations", {})
    report.equal(annotations.get("prometheus.io/scrape"), "true", f"{name}: prometheus.io/scrape")
    report.equal(annotations.get("prometheus.io/path"), "/metrics", f"{name}: prometheus.io/path")
    report.equal(annotations.get("prometheus.io/port"), str(http_port), f"{name}: prometheus.io/port is the HTTP port")
    for port in service["spec"]["ports"]:
        entry = container_port(container, port.get("targetPort", port["port"]))
        report.check(entry is not None and entry.get("protocol", "TCP") == port.get("protocol", "TCP"),
                     f"{name}: Service port {port.get('name')} targets a container port of its protocol")

    # Started as the pod would start it: the ports it opens are the container ports.
    sim = start_in_namespace(work / config_path.name, work, name)
    try:
        ready = sim.wait_ready()
        declared = {(p["containerPort"], p.get("protocol", "TCP")) for p in container["ports"]}
        report.equal(declared, served_ports(ready) | {(ready["http"], "TCP")}, f"{name}: container ports vs the ports served")
        report.equal(ready["http"], http_port, f"{name}: HTTP port served")
        for probe, path in (("livenessProbe", "/healthz"), ("readinessProbe", "/readyz")):
            check = subprocess.run(["nsenter", f"--target={sim.process.pid}", "--net", "--",
                                    str(repo / "deploy/image/healthcheck.sh"), path, str(http_port)],
                                   capture_output=True, text=True)
            report.equal(check.returncode, 0, f"{name}: {probe} GET {path} in the pod's namespace ({check.stderr.strip()!r})")
        report.equal(sim.stop(), 0, f"{name}: exit code after SIGTERM")
    except Exception as e:
        sim.kill()
        report.check(False, f"{name}: starting {config_path.name}: {e}")


manifests = sorted((repo / "deploy/k8s").glob("*.yaml"))
report.check([m.name for m in manifests] == ["plant.yaml", "station.yaml"], f"deploy/k8s has {[m.name for m in manifests]}")
build.mkdir(parents=True, exist_ok=True)
with tempfile.TemporaryDirectory(dir=build, prefix="deploy-k8s.") as tmp:
    for manifest in manifests:
        print(f"-- {manifest.relative_to(repo)}")
        work = pathlib.Path(tmp) / manifest.stem
        work.mkdir()
        check_manifest(manifest, work)
report.finish()
