#!/usr/bin/env python3
"""The sharded plant's manifests (deploy/k8s/sharded/) against the plant file and the binary.

- deploy/k8s/sharded/plant-shards.yaml is what deploy/k8s/render_shards.py renders
  from examples/plants/sharded-10000.json now (else: re-render it);
- it holds exactly a ConfigMap, a headless Service, a StatefulSet and a
  PodDisruptionBudget; the StatefulSet's replicas are the file's "shards", its
  serviceName the headless Service, its pods run `--shard auto` on the
  ConfigMap's plant file (which passes --check-config and names the pods' DNS
  names in "shard_host"), as the image's user, with /healthz and /readyz
  probes and Prometheus annotations on the file's HTTP port; the Service and
  the budget select the pods;
- resources: the memory request is the generator's figure for the largest
  shard, and that shard, started as its pod starts it (a network and UTS
  namespace whose host name is the pod's, so --shard auto reads the ordinal),
  fits in it once ready; it serves exactly the stations the generator assigns
  it, on their configured ports, and its GET /api/plant gives every station
  the generator's shard and the shard's DNS name.

The start needs root, unshare and nsenter (a part skipped without them).
Usage: check_k8s_shards.py SLMP_SIM_BINARY REPO_ROOT BUILD_DIR
"""
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile
import urllib.request

from report import Report, skip_test
from sim_process import SimProcess

try:
    import yaml
except ImportError:
    skip_test("python3-yaml is not installed (apt-get install python3-yaml, or run scripts/setup.sh)")

binary, repo, build = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
sys.path.insert(0, str(repo / "deploy/k8s"))
import render_shards  # noqa: E402

IMAGE_USER = 10001
PLANT_FILE = repo / "examples/plants/sharded-10000.json"
MANIFEST = repo / "deploy/k8s/sharded/plant-shards.yaml"
report = Report()


def mebibytes(quantity):
    report.check(quantity.endswith("Mi"), f"memory {quantity} in Mi")
    return int(quantity[:-2])


rendered = subprocess.run([sys.executable, str(repo / "deploy/k8s/render_shards.py"), str(PLANT_FILE)],
                          capture_output=True, text=True, check=True).stdout
report.check(rendered == MANIFEST.read_text(),
             f"{MANIFEST.relative_to(repo)} is stale: deploy/k8s/render_shards.py {PLANT_FILE.relative_to(repo)} > "
             f"{MANIFEST.relative_to(repo)}")
plant = json.loads(PLANT_FILE.read_text())
docs = {d["kind"]: d for d in yaml.safe_load_all(MANIFEST.read_text()) if d}
if not report.equal(sorted(docs), ["ConfigMap", "PodDisruptionBudget", "Service", "StatefulSet"], "kinds"):
    report.finish()
config_map, service, stateful_set, budget = (docs[k] for k in ("ConfigMap", "Service", "StatefulSet", "PodDisruptionBudget"))
name = stateful_set["metadata"]["name"]
spec = stateful_set["spec"]
pod = spec["template"]["spec"]
pod_labels = spec["template"]["metadata"]["labels"]
container = pod["containers"][0]
shards = plant["shards"]
http_port = plant["http"]["port"]

report.equal(spec["replicas"], shards, "StatefulSet replicas = the plant's shards")
report.equal(spec["serviceName"], service["metadata"]["name"], "StatefulSet serviceName = the headless Service")
report.equal(service["spec"].get("clusterIP"), "None", "the Service is headless (per-pod DNS names)")
report.check(service["spec"]["selector"].items() <= pod_labels.items(), "the Service selects the pods")
report.check(spec["selector"]["matchLabels"].items() <= pod_labels.items(), "the StatefulSet selects its pods")
report.check(budget["spec"]["selector"]["matchLabels"].items() <= pod_labels.items(), "the PodDisruptionBudget selects the pods")
report.equal(budget["spec"].get("maxUnavailable"), 1, "PodDisruptionBudget maxUnavailable")
report.equal(pod["securityContext"].get("runAsUser"), IMAGE_USER, "runAsUser (the image's user)")
report.equal(pod["securityContext"].get("runAsNonRoot"), True, "runAsNonRoot")
args = container["args"]
report.equal(args[args.index("--shard") + 1] if "--shard" in args else None, "auto", "--shard auto (the pod's ordinal)")
config_path = pathlib.PurePosixPath(args[args.index("--config") + 1])
mount = next(m for m in container["volumeMounts"] if pathlib.PurePosixPath(m["mountPath"]) == config_path.parent)
volume = next(v for v in pod["volumes"] if v["name"] == mount["name"])
report.equal(volume["configMap"]["name"], config_map["metadata"]["name"], f"{config_path.parent} is the ConfigMap")
served_plant = json.loads(config_map["data"][config_path.name])
report.equal(served_plant["shard_host"], f"{name}-{{shard}}.{service['metadata']['name']}", "shard_host: the pods' DNS names")
report.equal({k: v for k, v in served_plant.items() if k != "shard_host"}, plant, "the ConfigMap holds the plant file")
http_entry = next((p for p in container["ports"] if p["name"] == "http"), {})
report.equal(http_entry.get("containerPort"), http_port, "container port http = the plant's HTTP port")
for probe, path in (("livenessProbe", "/healthz"), ("readinessProbe", "/readyz")):
    report.equal(container[probe]["httpGet"], {"path": path, "port": "http"}, f"{probe}")
annotations = spec["template"]["metadata"]["annotations"]
report.equal(annotations, {"prometheus.io/scrape": "true", "prometheus.io/port": str(http_port),
                           "prometheus.io/path": "/metrics"}, "Prometheus scrapes every shard's /metrics")

build.mkdir(parents=True, exist_ok=True)
with tempfile.TemporaryDirectory(dir=build, prefix="deploy-k8s-shards.") as tmp:
    work = pathlib.Path(tmp)
    (work / "plant.json").write_text(config_map["data"]["plant.json"])
    check = subprocess.run([binary, "--check-config", str(work / "plant.json")], capture_output=True, text=True)
    report.check(check.returncode == 0, f"--check-config of the ConfigMap's plant: {check.stderr.strip()}")

    names = render_shards.station_names(plant)
    assignment = {station: render_shards.shard_of(station, shards) for station in names}
    sizes = [list(assignment.values()).count(k) for k in range(shards)]
    largest = sizes.index(max(sizes))
    memory_request = mebibytes(container["resources"]["requests"]["memory"])
    report.equal(memory_request, render_shards.BASE_MIB + (max(sizes) * render_shards.PER_STATION_KIB + 1023) // 1024,
                 "memory request: the generator's figure for the largest shard")
    report.equal(container["resources"]["limits"]["cpu"], str(plant["threads"]), "CPU limit = the plant's threads")

    tools = [t for t in ("unshare", "nsenter") if shutil.which(t) is None]
    if os.geteuid() != 0 or tools:
        report.skip_part("starting the largest shard as its pod", "needs root, unshare and nsenter")
        report.finish()
    # The pod: its own network (loopback only) and its own host name, the StatefulSet's NAME-K.
    ready = work / "ready.json"
    command = ["unshare", "--net", "--uts", "--", "sh", "-c",
               f'ip link set lo up && hostname {name}-{largest} && exec "$0" "$@"',
               binary] + args[:args.index("--shard")] + ["--shard", "auto", "--ready-file", str(ready)]
    command[command.index(str(config_path))] = str(work / "plant.json")
    sim = SimProcess(command, str(ready), str(work / "shard.log"))
    try:
        started = sim.wait_ready()
        mine = [s["name"] for s in started["stations"]]
        report.equal(mine, [s for s in names if assignment[s] == largest], f"shard {largest} serves its stations")
        report.equal({s["tcp"][0] for s in started["stations"]},
                     {20000 + int(s.split("-")[1]) for s in mine}, "on their configured ports")
        with open(f"/proc/{sim.process.pid}/status") as f:
            rss_mib = next(int(line.split()[1]) for line in f if line.startswith("VmRSS:")) / 1024
        print(f"shard {largest}: {len(mine)} stations, RSS {rss_mib:.1f} MiB once ready; memory request {memory_request} MiB")
        report.check(rss_mib < memory_request, f"the RSS of shard {largest} ({rss_mib:.1f} MiB) fits its memory request")
        fetch = subprocess.run(["nsenter", f"--target={sim.process.pid}", "--net", "--", sys.executable, "-c",
                                f"import urllib.request,sys; sys.stdout.write(urllib.request.urlopen("
                                f"'http://127.0.0.1:{http_port}/api/plant').read().decode())"],
                               capture_output=True, text=True)
        layout = json.loads(fetch.stdout or "{}")
        report.equal(layout.get("shard"), largest, "GET /api/plant: the shard that answers")
        report.equal(layout.get("shards"), shards, "GET /api/plant: shards")
        report.equal({s["name"]: s["shard"] for s in layout.get("stations", [])}, assignment,
                     "GET /api/plant: every station's shard is the generator's")
        report.check(all(s["host"] == f"{name}-{s['shard']}.{name}" for s in layout.get("stations", [])),
                     "GET /api/plant: every station's host is its shard's DNS name")
        report.equal(sim.stop(), 0, "exit code after SIGTERM")
    except Exception as e:
        sim.kill()
        report.check(False, f"starting shard {largest}: {e}")
report.finish()
