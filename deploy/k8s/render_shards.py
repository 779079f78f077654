#!/usr/bin/env python3
"""Renders the Kubernetes manifests of a sharded plant from its plant file.

One plant file (docs/plants.md, "Shards") with "shards": N becomes one
StatefulSet of N pods, each running `slmp-sim --config plant.json --shard auto`
(the pod's ordinal is its shard), and around it:

  ConfigMap            the plant file, with "shard_host" set to the pods' DNS names
  Service (headless)   NAME: pod K is NAME-K.NAME[.NAMESPACE.svc], so press-0421 is
                       reached at the host and port GET /api/plant gives for it
  StatefulSet          N replicas, Parallel start, probes /healthz and /readyz,
                       Prometheus scrape annotations on every pod, resources sized
                       from the largest shard (below)
  PodDisruptionBudget  at most one shard down at a time for voluntary disruptions

Resources are sized from measurements (docs/plants.md, "Shards"): memory
request = BASE + PER_STATION x the largest shard's stations (the idle RSS
measured with scripts/plant-memory.py, rounded up), limit = that plus
WRITTEN_PER_STATION for every station (room for each station's memory being
written); CPU request = CPU_MILLI_PER_STATION x the largest shard's stations
(the idle plant's measured CPU), limit = the file's "threads" cores.

The shard of each station is computed here exactly as slmp-sim computes it
(config/shard.cpp: rendezvous hashing of the name), so the generator knows the
largest shard without starting anything; tests/deploy/check_k8s_shards.py
checks both agree.

  deploy/k8s/render_shards.py examples/plants/sharded-10000.json > plant-shards.yaml
  deploy/k8s/render_shards.py plant.json --name line-3 --namespace plants --image registry/slmp-sim:0.1.0

Kustomize (Debian's kubernetes-client 1.20 embeds kustomize 2.0) cannot derive
replicas and resources from the plant file, hence this script; its output is
plain YAML that `kubectl apply -f -` or a kustomization's `resources` take.
"""
import argparse
import json
import re
import sys

# Measured on the 2-core VM (docs/plants.md, "Shards"): a 1000-station R08CPU shard.
BASE_MIB = 64                 # the process without stations, rounded up
PER_STATION_KIB = 64          # idle RSS a station (measured 50-52 KiB)
WRITTEN_PER_STATION_KIB = 1024  # a station whose D, W, R, ZR, M, B were all written (measured 904 KiB)
# Idle CPU of a station's scan loop: 37-45 % of a core per 1000 stations on main
# (2026-12-04), before idle stations stop ticking (issue 33); lower it then.
CPU_MILLI_PER_STATION = 0.5
MIN_CPU_MILLI = 100
HTTP_PORT = 8080
MASK = (1 << 64) - 1


def fnv1a(text):
    value = 0xCBF29CE484222325
    for byte in text.encode():
        value = ((value ^ byte) * 0x100000001B3) & MASK
    return value


def mix(z):
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
    return z ^ (z >> 31)


def shard_of(name, shards):
    """config/shard.cpp's shard_of: the shard with the highest score, the lowest on a tie."""
    h = fnv1a(name)
    scores = [mix(h ^ ((0x9E3779B97F4A7C15 * (k + 1)) & MASK)) for k in range(shards)]
    return scores.index(max(scores))


def expand(text, i):
    """A template string's placeholders ({i}, {i:03}, {i+100}) for station i (config/plant_config.cpp)."""
    def one(match):
        expression, _, width = match.group(1).partition(":")
        if not re.fullmatch(r"[0-9i+\-*() ]+", expression):
            raise SystemExit(f"render_shards: '{text}': a placeholder this script cannot read")
        value = eval(expression, {"__builtins__": {}}, {"i": i})  # digits, i, + - * ( ) only
        return str(value).zfill(int(width[1:])) if width else str(value)
    return re.sub(r"\{([^}]*)\}", one, text)


def station_names(plant):
    """Every station's name, in the file's order, as slmp-sim names them."""
    names = []
    for entry in plant["stations"]:
        if "template" in entry or "count" in entry:
            name = entry.get("name", entry.get("template", {}).get("name"))
            first = entry.get("first", 1)
            for i in range(first, first + entry["count"]):
                names.append(expand(name, i) if name else f"station-{i}")
        else:
            names.append(entry.get("name", f"station-{len(names) + 1}"))
    return names


def render(plant, name, namespace, image):
    shards = plant.get("shards", 1)
    threads = plant.get("threads", 2)
    http_port = plant.get("http", {}).get("port", HTTP_PORT)
    if plant.get("bind", "0.0.0.0") != "0.0.0.0":
        raise SystemExit('render_shards: a pod\'s stations listen on "bind": "0.0.0.0" (the pod\'s own address); '
                         f'the file binds {plant.get("bind")}')
    names = station_names(plant)
    sizes = [0] * shards
    for station in names:
        sizes[shard_of(station, shards)] += 1
    largest = max(sizes)
    memory_request = BASE_MIB + (largest * PER_STATION_KIB + 1023) // 1024
    memory_limit = memory_request + (largest * WRITTEN_PER_STATION_KIB + 1023) // 1024
    cpu_request = max(MIN_CPU_MILLI, round(largest * CPU_MILLI_PER_STATION))
    plant = dict(plant)
    domain = f".{namespace}.svc" if namespace else ""
    plant.setdefault("shard_host", f"{name}-{{shard}}.{name}{domain}")
    labels = {"app.kubernetes.io/name": "slmp-sim", "app.kubernetes.io/instance": name}
    meta = {"name": name, "labels": labels}
    if namespace:
        meta["namespace"] = namespace
    config_map = {"apiVersion": "v1", "kind": "ConfigMap", "metadata": meta,
                  "data": {"plant.json": json.dumps(plant, indent=2) + "\n"}}
    service = {"apiVersion": "v1", "kind": "Service", "metadata": meta,
               "spec": {"clusterIP": "None", "selector": labels,
                        "ports": [{"name": "http", "port": http_port, "targetPort": "http", "protocol": "TCP"}]}}
    container = {
        "name": "slmp-sim", "image": image, "imagePullPolicy": "IfNotPresent",
        "args": ["--config", "/etc/slmp-sim/plant.json", "--shard", "auto"],
        "ports": [{"name": "http", "containerPort": http_port, "protocol": "TCP"}],
        "livenessProbe": {"httpGet": {"path": "/healthz", "port": "http"}, "periodSeconds": 10, "failureThreshold": 3},
        "readinessProbe": {"httpGet": {"path": "/readyz", "port": "http"}, "periodSeconds": 2, "failureThreshold": 3},
        "resources": {"requests": {"cpu": f"{cpu_request}m", "memory": f"{memory_request}Mi"},
                      "limits": {"cpu": str(threads), "memory": f"{memory_limit}Mi"}},
        "securityContext": {"allowPrivilegeEscalation": False, "readOnlyRootFilesystem": True,
                            "capabilities": {"drop": ["ALL"]}},
        "volumeMounts": [{"name": "config", "mountPath": "/etc/slmp-sim", "readOnly": True}],
    }
    stateful_set = {
        "apiVersion": "apps/v1", "kind": "StatefulSet", "metadata": meta,
        "spec": {
            "serviceName": name, "replicas": shards, "podManagementPolicy": "Parallel",
            "selector": {"matchLabels": labels},
            "template": {
                "metadata": {"labels": labels,
                             "annotations": {"prometheus.io/scrape": "true", "prometheus.io/port": str(http_port),
                                             "prometheus.io/path": "/metrics"}},
                "spec": {"securityContext": {"runAsNonRoot": True, "runAsUser": 10001, "runAsGroup": 10001,
                                             "fsGroup": 10001, "seccompProfile": {"type": "RuntimeDefault"}},
                         "terminationGracePeriodSeconds": 15,
                         "containers": [container],
                         "volumes": [{"name": "config", "configMap": {"name": name}}]}}}}
    budget = {"apiVersion": "policy/v1", "kind": "PodDisruptionBudget", "metadata": meta,
              "spec": {"maxUnavailable": 1, "selector": {"matchLabels": labels}}}
    header = (f"# Rendered by deploy/k8s/render_shards.py: {len(names)} stations over {shards} shards "
              f"(largest {largest}, smallest {min(sizes)}); pod K serves shard K.\n"
              f"# Station S is at the host and ports GET /api/plant/stations/S gives: "
              f"{plant['shard_host'].replace('{shard}', 'K')}.\n")
    return header, [config_map, service, stateful_set, budget]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("plant", help="the plant file (docs/plants.md)")
    ap.add_argument("--name", default="slmp-plant", help="the StatefulSet's, Service's and pods' name")
    ap.add_argument("--namespace", default="", help="give it for DNS names that work from other namespaces")
    ap.add_argument("--image", default="localhost/slmp-sim:0.1.0")
    args = ap.parse_args()
    with open(args.plant) as f:
        plant = json.load(f)
    if "stations" not in plant:
        raise SystemExit("render_shards: the file has no \"stations\"; a sharded plant is a plant file (docs/plants.md)")
    header, documents = render(plant, args.name, args.namespace, args.image)
    sys.stdout.write(header + "".join("---\n" + json.dumps(d, indent=2) + "\n" for d in documents))


if __name__ == "__main__":
    main()
