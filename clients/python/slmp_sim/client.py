"""A small client for slmp-sim's HTTP API (docs/api.md), standard library only."""
import json
import os
import urllib.error
import urllib.parse
import urllib.request


class SlmpSimError(Exception):
    """The API answered an error: ``status`` and the API's ``message`` (which names the fix)."""

    def __init__(self, status, message, body=None):
        super().__init__("HTTP %d: %s" % (status, message))
        self.status = status
        self.message = message
        self.body = body or {}


class WaitTimeout(SlmpSimError):
    """A wait ran out (408); ``value`` is the last value the simulator saw."""

    @property
    def value(self):
        return self.body.get("value")


class Clock:
    """The CPU's virtual clock: ``freeze()``, ``step(scans=5)`` / ``step(ms=1500)``, ``realtime(speed)``."""

    def __init__(self, sim):
        self._sim = sim

    def get(self):
        return self._sim.request("GET", "/api/clock")

    def freeze(self):
        return self._sim.request("PUT", "/api/clock", {"mode": "frozen"})

    def realtime(self, speed=None):
        body = {"mode": "realtime"}
        if speed is not None:
            body["speed"] = speed
        return self._sim.request("PUT", "/api/clock", body)

    def step(self, scans=None, ms=None):
        if (scans is None) == (ms is None):
            raise ValueError("step(scans=N) or step(ms=N), one of them")
        return self._sim.request("POST", "/api/clock/step", {"scans": scans} if scans is not None else {"ms": ms})


class Faults:
    """The faults of the running scenarios (``GET/PUT /api/faults``)."""

    def __init__(self, sim):
        self._sim = sim

    def list(self):
        return self._sim.request("GET", "/api/faults")["faults"]

    def enable(self, fault_id, on=True):
        path = "/api/faults/" + urllib.parse.quote(fault_id, safe="")
        return self._sim.request("PUT", path, {"enabled": bool(on)})

    def disable(self, fault_id):
        return self.enable(fault_id, False)


class Scenarios:
    """Scenarios loaded while the simulator runs (``/api/scenarios``)."""

    def __init__(self, sim):
        self._sim = sim

    def list(self):
        return self._sim.request("GET", "/api/scenarios")["scenarios"]

    def load(self, file=None, body=None):
        """``load(file="scenarios/examples/tank.json")`` (relative to the simulator's directory) or ``load(body={...})``."""
        if (file is None) == (body is None):
            raise ValueError("load(file=...) or load(body={...}), one of them")
        return self._sim.request("POST", "/api/scenarios", {"file": str(file)} if file is not None else body)

    def stop(self, name):
        return self._sim.request("DELETE", "/api/scenarios/" + urllib.parse.quote(name, safe=""))


class Program:
    """The CPU's PLC program (``/api/program``, docs/program.md). Loading and
    unloading need the CPU in STOP, as GX Works' *Write to PLC* does: ``load``
    stops the CPU, writes the program and puts the switch back to RUN unless
    ``run=False``."""

    def __init__(self, sim):
        self._sim = sim

    def get(self):
        return self._sim.request("GET", "/api/program")

    def load(self, path=None, text=None, name=None, run=True):
        """``load(path="line1.csv")`` (a GX Works CSV list or a text list, read here) or ``load(text="LD X0\nOUT Y0\nEND")``."""
        if (path is None) == (text is None):
            raise ValueError("load(path=...) or load(text=...), one of them")
        if path is not None:
            with open(path, "rb") as f:
                data = f.read()
            name = name or os.path.basename(str(path))
        else:
            data = text.encode("utf-8")
            name = name or "program.il"
        self._sim.set_switch("STOP")
        result = self._sim.request_bytes("PUT", "/api/program" + self._sim._query(file=name), data)
        if run:
            self._sim.set_switch("RUN")
        return result

    def unload(self, run=True):
        self._sim.set_switch("STOP")
        result = self._sim.request("DELETE", "/api/program")
        if run:
            self._sim.set_switch("RUN")
        return result

    def source(self, format="text"):
        """The program written back: ``"text"`` (str) or ``"csv"`` (GX Works' UTF-16 bytes)."""
        raw = self._sim.request("GET", "/api/program/source" + self._sim._query(format=format))
        return raw.decode("utf-8") if format == "text" else raw


class SlmpSim:
    """The HTTP API of one simulator. ``tcp_port``/``udp_port`` are its SLMP ports, for the client under test."""

    def __init__(self, http_port, host="127.0.0.1", tcp_port=None, udp_port=None, timeout=30.0):
        self.host = host
        self.http_port = http_port
        self.tcp_port = tcp_port
        self.udp_port = udp_port
        self.timeout = timeout
        self.clock = Clock(self)
        self.fault = Faults(self)
        self.scenario = Scenarios(self)
        self.program = Program(self)

    # -- plumbing ---------------------------------------------------------
    def request(self, method, path, body=None, timeout=None):
        data = None if body is None else json.dumps(body).encode()
        return self.request_bytes(method, path, data, timeout, "application/json")

    def request_bytes(self, method, path, data, timeout=None, content_type="application/octet-stream"):
        req = urllib.request.Request("http://%s:%d%s" % (self.host, self.http_port, path), data=data, method=method)
        if data is not None:
            req.add_header("Content-Type", content_type)
        try:
            with urllib.request.urlopen(req, timeout=timeout or self.timeout) as response:
                raw = response.read()
                if response.headers.get_content_type() != "application/json":
                    return raw
                return json.loads(raw)
        except urllib.error.HTTPError as e:
            raw = e.read()
            try:
                parsed = json.loads(raw)
            except ValueError:
                parsed = {"error": raw.decode(errors="replace")}
            cls = WaitTimeout if e.code == 408 else SlmpSimError
            raise cls(e.code, parsed.get("error", ""), parsed) from None

    @staticmethod
    def _query(**params):
        given = {k: v for k, v in params.items() if v is not None}
        return ("?" + urllib.parse.urlencode(given)) if given else ""

    # -- devices ----------------------------------------------------------
    def set(self, address, values, as_=None):
        """``set("D100", 5)``, ``set("D100", [1, 2])``, ``set("M0", True)``, ``set("D200", "TEXT")``."""
        if isinstance(values, str):
            body = {"string": values}
        else:
            body = {"values": list(values) if isinstance(values, (list, tuple)) else [values]}
        return self.request("PUT", "/api/devices/%s%s" % (address, self._query(**{"as": as_})), body)

    def get(self, address, count=1, as_=None):
        """One value (``count=1``) or a list; ``as_="dwords"``, ``"bits"``, ``"string"``."""
        r = self.request("GET", "/api/devices/%s%s" % (address, self._query(count=count if count != 1 else None,
                                                                            **{"as": as_})))
        if "string" in r:
            return r["string"]
        return r["values"][0] if count == 1 else r["values"]

    def wait(self, address, equals=None, not_equals=None, greater=None, less=None, changes=False, timeout_ms=10000,
             as_=None):
        """Blocks until the condition holds and returns the value; raises ``WaitTimeout`` (with ``.value``)."""
        params = {"equals": equals, "not_equals": not_equals, "greater": greater, "less": less,
                  "timeout_ms": timeout_ms, "as": as_}
        if changes:
            params["changes"] = "true"
        r = self.request("GET", "/api/devices/%s/wait%s" % (address, self._query(**params)),
                         timeout=timeout_ms / 1000.0 + self.timeout)
        return r["value"]

    # -- state, snapshots -------------------------------------------------
    def state(self):
        return self.request("GET", "/api/state")

    def set_switch(self, position):
        return self.request("PUT", "/api/state", {"switch": position})

    def snapshot(self, name, file=None):
        body = {"name": name}
        if file is not None:
            body["file"] = str(file)
        return self.request("POST", "/api/snapshots", body)

    def snapshots(self):
        return self.request("GET", "/api/snapshots")["snapshots"]

    def restore(self, name, drop_connections=False):
        return self.request("POST", "/api/snapshots/%s/restore" % urllib.parse.quote(name, safe=""),
                            {"drop_connections": drop_connections})

    def delete_snapshot(self, name):
        return self.request("DELETE", "/api/snapshots/" + urllib.parse.quote(name, safe=""))

    def reset(self, drop_connections=False):
        return self.request("POST", "/api/reset", {"drop_connections": drop_connections})

    def info(self):
        return self.request("GET", "/api/info")
