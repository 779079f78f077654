// The settings table (config/settings.hpp) and what is generated from it.
#include "config/settings.hpp"

#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
#include "config/json_path.hpp"
#include "frontends/face.hpp"

namespace slmp::config {

namespace {

using S = Section;
using T = SettingType;
using F = FlagArg;

// clang-format off
constexpr Setting kSettings[] = {
    // --- the command line alone ---------------------------------------------------------------------------------
    {.section = S::CommandLine, .key = "", .flag = "help,h", .type = T::None, .help = "print this help and exit"},
    {.section = S::CommandLine, .key = "", .flag = "version", .type = T::None, .help = "print the version and exit"},
    {.section = S::CommandLine, .key = "", .flag = "list-profiles", .type = T::None,
     .help = "list the built-in CPU profiles and exit"},
    {.section = S::CommandLine, .key = "", .flag = "config,c", .type = T::String, .flag_arg = F::Text,
     .help = "JSON configuration file (see docs/configuration.md)"},
    {.section = S::CommandLine, .key = "", .flag = "check-config", .type = T::String, .flag_arg = F::Text,
     .help = "check this configuration file (and the profile, scenarios and snapshot it names) and exit: 0 good, 2 with the error"},
    {.section = S::CommandLine, .key = "", .flag = "ready-file", .type = T::String, .flag_arg = F::Text,
     .help = "write {\"tcp\":[...],\"udp\":[...],\"http\":N,\"pid\":N} here once listening"},
    {.section = S::CommandLine, .key = "", .flag = "record", .type = T::String, .flag_arg = F::Text,
     .help = "record every request and response to this JSON-lines file (docs/scenarios.md)"},
    {.section = S::CommandLine, .key = "", .flag = "record-pcap", .type = T::String, .flag_arg = F::Text,
     .help = "capture every request and response to this pcap file for Wireshark (docs/scenarios.md)"},
    {.section = S::CommandLine, .key = "", .flag = "clock", .type = T::Choice, .flag_arg = F::Text,
     .choices = "realtime|frozen", .default_text = "realtime",
     .help = "realtime (default) or frozen: no scan until POST /api/clock/step or PUT /api/clock (docs/ci.md)"},
    {.section = S::CommandLine, .key = "", .flag = "shard", .type = T::String, .flag_arg = F::Text,
     .help = "serve shard K of N of the plant: K/N, K (N: the file's \"shards\"), auto or auto/N (K: the host name's "
             "trailing -K, a StatefulSet pod's ordinal) (docs/plants.md)"},
    {.section = S::CommandLine, .key = "", .flag = "snapshot", .type = T::String, .flag_arg = F::Text,
     .help = "start from a station snapshot file saved from GET /api/snapshots/{name}/file (docs/ci.md)"},

    // --- a plant ---------------------------------------------------------------------------------------------------
    {.section = S::Plant, .key = "threads", .flag = "threads", .type = T::Integer, .flag_arg = F::Unsigned,
     .min = 1, .max = 256, .default_text = "the machine's cores",
     .help = "threads serving the stations (default: the machine's cores; a station's connections stay on its thread)",
     .fix = "leave \"threads\" out to use every core, or use 1 to 256",
     .doc = "threads serving the stations ([plants.md](plants.md#threads))", .doc_table = "station",
     .flag_fix = "use 1 to 256 (default: the machine's cores)"},
    {.section = S::Plant, .key = "shards", .flag = "", .type = T::Integer, .min = 1, .max = 1000, .default_text = "1",
     .help = "processes the plant is split over: N for --shard K and --shard auto, and the manifests' replicas "
             "([plants.md](plants.md#shards-one-plant-file-n-processes))",
     .fix = "use 1 to 1000 shards", .doc_table = "station"},
    {.section = S::Plant, .key = "shard_host", .flag = "", .type = T::String, .default_text = "each station's bind address",
     .help = "the host name of shard {shard} in GET /api/plant, e.g. \"slmp-plant-{shard}.slmp-plant\" "
             "([plants.md](plants.md#shards-one-plant-file-n-processes))",
     .doc_table = "station"},
    {.section = S::Plant, .key = "metrics_by", .flag = "", .type = T::Choice, .choices = "auto|station|profile",
     .default_text = "\"auto\"",
     .help = "the plant's /metrics: a series set per station, or summed per profile; auto: per station up to 1000 "
             "stations ([plants.md](plants.md#metrics-of-a-large-plant))",
     .doc_table = "station"},
    {.section = S::Plant, .key = "stations", .flag = "", .type = T::Array, .default_text = "none",
     .help = "the stations of a plant, each an object of the keys below or a template ([plants.md](plants.md))",
     .doc_table = "station"},
    // A template entry of "stations" (plant_config.cpp): its keys sit beside the station keys it may also hold.
    {.section = S::Template, .key = "template", .flag = "", .type = T::Object, .default_text = "none",
     .help = "the keys of every station it makes ({i} placeholders)",
     .doc = "a template entry: the station keys of every station it makes, with `{i}` placeholders in strings and "
            "`\"20000+i\"` port expressions ([plants.md](plants.md))",
     .doc_table = "station"},
    {.section = S::Template, .key = "count", .flag = "", .type = T::Integer, .min = 1, .max = 10000,
     .default_text = "required", .help = "how many stations the template makes",
     .fix = "give the number of stations the template makes", .doc_type = "number",
     .doc_table = "station", .below_min = "must be at least 1", .plain_range = true},
    {.section = S::Template, .key = "first", .flag = "", .type = T::Integer, .max = 1000000, .default_text = "1",
     .help = "the template's first `i`", .doc_type = "number", .doc_table = "station", .plain_range = true},

    // --- one station -----------------------------------------------------------------------------------------------
    {.section = S::Station, .key = "profile", .flag = "profile,p", .type = T::String, .flag_arg = F::Text,
     .default_text = "\"R08CPU\"",
     .help = "CPU profile: a built-in name (default R08CPU) or a profile .json file",
     .doc = "built-in profile name (case-insensitive) or a path to a profile `.json`"},
    {.section = S::Station, .key = "bind", .flag = "bind,b", .type = T::String, .flag_arg = F::Text,
     .default_text = "\"0.0.0.0\"", .help = "address to listen on (default 0.0.0.0)",
     .doc = "IP address to listen on"},
    {.section = S::Station, .key = "ports", .flag = "", .type = T::Array, .default_text = "TCP 5000 and UDP 5000",
     .help = "one object per port (below)", .holds = S::Port},
    {.section = S::Station, .key = "tcp_port", .flag = "tcp-port", .type = T::Integer, .flag_arg = F::UnsignedList,
     .min = 0, .max = 65535, .help = "TCP port(s) to serve; 0 = any free port (default 5000)",
     .fix = "use 0-65535 (0 = any free port)",
     .doc = "the short form of `ports`: the TCP port number only (defaults for the other keys); a transport left "
            "out is not served; not together with `ports`",
     .flag_fix = "not a port number; use 0-65535 (0 = any free port)"},
    {.section = S::Station, .key = "udp_port", .flag = "udp-port", .type = T::Integer, .flag_arg = F::UnsignedList,
     .min = 0, .max = 65535, .help = "UDP port(s) to serve; 0 = any free port (default 5000)",
     .fix = "use 0-65535 (0 = any free port)",
     .doc = "the short form of `ports`: the UDP port number only, as `tcp_port`",
     .flag_fix = "not a port number; use 0-65535 (0 = any free port)"},
    {.section = S::Station, .key = "max_request_bytes", .flag = "max-request-bytes", .type = T::Integer,
     .flag_arg = F::Size, .min = 64, .max = 1 << 20, .default_text = "8192",
     .help = "largest request frame accepted (default 8192)", .fix = "use 64 to 1048576 (default 8192)",
     .doc = "largest request frame; a larger length field closes a TCP connection / drops a datagram"},
    {.section = S::Station, .key = "upstream", .flag = "upstream", .type = T::String, .flag_arg = F::Text,
     .default_text = "none",
     .help = "proxy mode: forward every SLMP request to the PLC or SLMP server at HOST:PORT (TCP) and return its answer "
             "(docs/twin.md)",
     .doc = "proxy mode: every SLMP request goes on to the PLC or SLMP server at `HOST:PORT` over one TCP connection and "
            "its answer comes back; faults, limits and recording still apply here ([twin.md](twin.md#proxy))"},
    {.section = S::Station, .key = "upstream_timeout_ms", .flag = "upstream-timeout", .type = T::Integer,
     .flag_arg = F::Real, .min = 1, .max = 600000, .default_text = "3000",
     .help = "proxy mode: seconds the upstream has to answer a request before the client gets CF71 (default 3)",
     .fix = "use 1 to 600000 ms (default 3000)",
     .doc = "proxy mode: how long the upstream has to connect and answer; then the client gets CF71 and the "
            "connection is opened afresh for the next request",
     .flag_scale = 1000, .flag_fix = "use 0.001 to 600 seconds (default 3)"},
    {.section = S::Station, .key = "compare", .flag = "compare", .type = T::Boolean, .default_text = "`false`",
     .help = "differential mode (with --upstream): serve each request here too and report every difference between "
             "this station's answer and the upstream's; clients get the upstream's (docs/twin.md)",
     .doc = "differential mode (with `upstream`): each request is served from this station's own memory and profile "
            "as well, and every difference from the upstream's answer is logged, listed at `GET /api/compare` and "
            "counted in `slmp_compare_total`; the clients get the upstream's answer ([twin.md](twin.md#compare))"},
    {.section = S::Station, .key = "compare_slack_ms", .flag = "compare-slack", .type = T::Integer,
     .flag_arg = F::Real, .min = 0, .max = 600000, .default_text = "50",
     .help = "differential mode: answer times are far apart (a \"time\" difference) when the longer is more than "
             "twice the shorter plus this many seconds (default 0.05)",
     .fix = "use 0 to 600000 ms (default 50)",
     .doc = "differential mode: answer times are far apart — a `time` difference — when the longer is more than twice "
            "the shorter plus this ([twin.md](twin.md#compare))",
     .flag_scale = 1000, .flag_fix = "use 0 to 600 seconds (default 0.05)"},
    {.section = S::Station, .key = "device_sizes", .flag = "", .type = T::Object, .default_text = "the profile's",
     .help = "points per device area, overriding the profile (`X`, `Y`, `M`, `L`, `F`, `V`, `B`, `SB`, `S`, `SM`, "
             "`D`, `W`, `SW`, `SD`, `R`, `ZR`, `RD`, `Z`, `LZ`, `T`, `ST`, `C`, `LT`, `LST`, `LC`, and the CPU "
             "buffer memory `G`, `HG`)"},
    {.section = S::Station, .key = "devices", .flag = "", .type = T::Object, .default_text = "—",
     .help = "initial values by address (below)"},
    {.section = S::Station, .key = "modules", .flag = "", .type = T::Array, .default_text = "none",
     .help = "intelligent function modules with buffer memory ([below](#modules-networks-and-cpus))", .holds = S::Module},
    {.section = S::Station, .key = "networks", .flag = "", .type = T::Array, .default_text = "none",
     .help = "network modules and their link devices ([below](#modules-networks-and-cpus))", .holds = S::Network},
    {.section = S::Station, .key = "routes", .flag = "", .type = T::Array, .default_text = "derived",
     .help = "routing parameters: `[{\"network\": 3, \"via_network\": 1, \"via_station\": 2}]` — the way to "
             "another network instead of the derived one ([plants.md](plants.md#routing-parameters))",
     .holds = S::Route},
    {.section = S::Station, .key = "node_search", .flag = "", .type = T::Object, .default_text = "none",
     .help = "node search by broadcast for a station whose profile serves the node commands: `{\"port\": 45237, "
             "\"max_delay_ms\": 1500}` ([nodes.md](nodes.md#node-search-over-udp))", .holds = S::NodeSearch},
    {.section = S::Station, .key = "cpus", .flag = "", .type = T::Array, .default_text = "none",
     .help = "CPU No.2–4 of a multi-CPU system ([below](#modules-networks-and-cpus))", .holds = S::MultiCpu},
    {.section = S::Station, .key = "redundant", .flag = "", .type = T::Object, .default_text = "none",
     .help = "one CPU of a redundant pair: `{\"pair\": \"press-b\", \"system\": \"A\"}` "
             "([plants.md](plants.md#redundant-pairs))", .holds = S::Redundant},
    {.section = S::Station, .key = "multidrop", .flag = "", .type = T::Object, .default_text = "none",
     .help = "a multidrop station behind another station's serial module: `{\"via\": \"line-1\", \"start_io\": "
             "\"0040\", \"number\": 3}` ([plants.md](plants.md#multidrop-stations))", .holds = S::Multidrop},

    // --- "modules", "networks", "cpus": what is mounted beside CPU No.1 (hardware_config.cpp) --------------------------
    // The order of each object's rows is the order its unknown-key error lists them.
    {.section = S::Module, .key = "start_io", .flag = "", .type = T::String, .default_text = "required",
     .help = "the module's start I/O number, 4 hex digits (`\"0030\"` → reached as `U3\\G…`, Extend Unit module number "
             "0003)", .required = true},
    {.section = S::Module, .key = "model", .flag = "", .type = T::String, .default_text = "—", .help = "a name, for logs"},
    {.section = S::Module, .key = "buffer_words", .flag = "", .type = T::Integer, .max = 16 * 1024 * 1024,
     .default_text = "required", .help = "buffer memory size in words", .doc_type = "number", .required = true,
     .plain_range = true},
    {.section = S::Module, .key = "head_address", .flag = "", .type = T::String, .default_text = "0",
     .help = "Extend Unit (0601/1601) start address of buffer word 0, hex — from the module table of the SLMP Reference "
             "Manual §5.5 (e.g. `\"1008\"` for a Q62DA). Module numbers 03E0–03E3 need no entry: they reach the CPU "
             "buffer memory of CPU No.1–4 (real-CPU measurements) with head address 0 (**chosen**: byte address = "
             "buffer word × 2)"},
    {.section = S::Network, .key = "number", .flag = "", .type = T::Integer, .min = 1, .max = 239,
     .default_text = "required", .help = "network No. 1–239, reached as `J1\\W100`", .fix = "use 1-239",
     .doc_type = "number", .required = true, .below_min = "network numbers start at 1", .plain_range = true},
    {.section = S::Network, .key = "station", .flag = "", .type = T::Integer, .min = 1, .max = 65534,
     .default_text = "not set",
     .help = "the station No. (1–120) of this station's module on that network: requests routed through another "
             "station's network/Ethernet module reach this CPU by it ([plants.md](plants.md#networks-and-routes)); "
             "121–65534 (a CC-Link IE TSN network's numbering) only as station 7C of the station-number-extended "
             "frame ([plants.md](plants.md#extended-station-numbers)); not set: the link devices only",
     .fix = "use 1-65534", .doc_type = "number", .below_min = "station numbers start at 1", .plain_range = true},
    {.section = S::Network, .key = "master", .flag = "", .type = T::Boolean, .default_text = "the lowest station No.",
     .help = "`true`: this station is the network's control/master station (routes with station No. 7D/7E); one a "
             "network"},
    {.section = S::Network, .key = "send", .flag = "", .type = T::Array,
     .default_text = "256 LB and 256 LW from (station − 1) × 256",
     .help = "the LB/LW ranges this station sends to the network's other stations at each link scan, e.g. "
             "`[\"W100-W1FF\", \"B100-B1FF\"]` (B in whole words) ([plants.md](plants.md#link-devices))"},
    {.section = S::Network, .key = "device_sizes", .flag = "", .type = T::Object,
     .default_text = "16384, 16384, 32768, 512, 131072, 512", .help = "link device sizes: X, Y, B, SB, W, SW"},
    // --- "redundant" and "multidrop": a plant station's place in a pair or on a multidrop line (hardware_config.cpp) ----
    {.section = S::Redundant, .key = "pair", .flag = "", .type = T::String, .default_text = "required",
     .help = "the name of the pair's other CPU, a station of the same plant", .required = true},
    {.section = S::Redundant, .key = "system", .flag = "", .type = T::Choice, .choices = "A|B", .default_text = "\"A\"",
     .help = "system A (control at power-on) or B; the other CPU is the other system", .fix = "use \"A\" or \"B\"",
     .noun = "system"},
    {.section = S::Redundant, .key = "switchover_ms", .flag = "", .type = T::Number, .max = 60000,
     .default_text = "100", .help = "how long a system switch takes (requests by role answer 4248 meanwhile)",
     .fix = "use 0 to 60000 ms (default 100)"},
    {.section = S::Redundant, .key = "tracking", .flag = "", .type = T::Array,
     .default_text = "M, L, B, D, W and the timers' and counters' current values, whole",
     .help = "the device ranges the control system copies to the standby at each END, e.g. "
             "`[\"D0-D999\", \"M0-M1023\", \"TN\"]` (bit devices in whole words; given on one CPU or the same on "
             "both) ([plants.md](plants.md#tracking))"},
    {.section = S::Multidrop, .key = "via", .flag = "", .type = T::String, .default_text = "required",
     .help = "the station whose serial module it hangs on", .required = true},
    {.section = S::Multidrop, .key = "start_io", .flag = "", .type = T::String, .default_text = "required",
     .help = "that serial module's start I/O, 4 hex digits `\"0000\"`–`\"1FF0\"` (the route's module I/O is it ÷ 16)",
     .required = true},
    {.section = S::Multidrop, .key = "number", .flag = "", .type = T::Integer, .max = 31, .default_text = "required",
     .help = "the multidrop station No. 0–31", .fix = "use 0-31", .doc_type = "number", .required = true,
     .plain_range = true},
    {.section = S::Route, .key = "network", .flag = "", .type = T::Integer, .min = 1, .max = 239,
     .default_text = "required", .help = "the transfer destination network No. 1–239: a network this station is not on",
     .fix = "use 1-239", .doc_type = "number", .required = true, .below_min = "network numbers start at 1",
     .plain_range = true},
    {.section = S::Route, .key = "via_network", .flag = "", .type = T::Integer, .min = 1, .max = 239,
     .default_text = "required",
     .help = "the relay destination network No.: one of this station's `networks` with a station No.",
     .fix = "use 1-239", .doc_type = "number", .required = true, .below_min = "network numbers start at 1",
     .plain_range = true},
    {.section = S::Route, .key = "via_station", .flag = "", .type = T::Integer, .min = 1, .max = 65534,
     .default_text = "required",
     .help = "the relay destination station No. on `via_network`: the station that passes the request on (or serves "
             "it, when it is on `network`)",
     .fix = "use 1-65534", .doc_type = "number", .required = true, .below_min = "station numbers start at 1",
     .plain_range = true},
    {.section = S::NodeSearch, .key = "port", .flag = "", .type = T::Integer, .min = 1, .max = 65535,
     .default_text = "required",
     .help = "the UDP port node search broadcasts go to (the manual's B0B5 = 45237); every node station of the host may "
             "give the same one: it is bound with SO_REUSEADDR to the broadcast address of `bind` (127.x.x.x: "
             "127.255.255.255; otherwise 0.0.0.0)",
     .fix = "use 1-65535", .doc_type = "number", .required = true, .below_min = "port 0 is no port",
     .plain_range = true},
    {.section = S::NodeSearch, .key = "max_delay_ms", .flag = "", .type = T::Integer, .max = 60000,
     .default_text = "1500",
     .help = "each answer to a broadcast node search waits a random 0–this many ms on the station's clock (the "
             "manual's 0–1500 ms; 0: at once)",
     .fix = "use 0-60000", .doc_type = "number", .plain_range = true},
    {.section = S::MultiCpu, .key = "number", .flag = "", .type = T::Integer, .min = 2, .max = 4,
     .default_text = "required", .help = "2, 3 or 4: reached with module I/O 03E1–03E3 (03E0 and 03FF are CPU No.1)",
     .fix = "use 2, 3 or 4", .doc_type = "number", .required = true,
     .below_min = "CPU No.1 is the one configured at the top level", .plain_range = true},
    {.section = S::MultiCpu, .key = "profile", .flag = "", .type = T::String, .default_text = "required",
     .help = "as at the top level, for that CPU", .required = true},
    {.section = S::MultiCpu, .key = "device_sizes", .flag = "", .type = T::Object, .default_text = "the profile's",
     .help = "as at the top level, for that CPU"},
    {.section = S::MultiCpu, .key = "devices", .flag = "", .type = T::Object, .default_text = "—",
     .help = "as at the top level, for that CPU"},

    {.section = S::Station, .key = "log_level", .flag = "log-level,l", .type = T::Choice, .flag_arg = F::Text,
     .choices = "trace|debug|info|warn|error|off", .default_text = "\"info\"",
     .help = "trace, debug, info, warn, error or off (default info)",
     .fix = "use trace, debug, info, warn, error or off", .noun = "log level"},
    {.section = S::Station, .key = "name", .flag = "", .type = T::String, .default_text = "—",
     .help = "the station's name in a plant ([plants.md](plants.md))"},
    {.section = S::Station, .key = "scenarios", .flag = "scenario", .type = T::Array, .flag_arg = F::TextList,
     .default_text = "none",
     .help = "run a scenario file (values that move, logic, faults, replay); repeatable (docs/scenarios.md)",
     .doc = "scenario files to run, relative to this file (added to `--scenario`)", .doc_type = "array of paths"},
    {.section = S::Station, .key = "http", .flag = "", .type = T::Object, .default_text = "on, port 8080",
     .help = "the HTTP API, metrics and web monitor ([below](#http-api-http))", .holds = S::Http},
    {.section = S::Station, .key = "cpu", .flag = "", .type = T::Object, .default_text = "none",
     .help = "the running CPU ([below](#the-running-cpu-cpu))", .holds = S::Cpu},
    {.section = S::Station, .key = "labels", .flag = "labels", .type = T::Array, .flag_arg = F::TextList,
     .default_text = "none",
     .help = "declare global labels from this JSON or GX Works3 CSV file; repeatable (docs/labels.md)",
     .doc = "global labels: a list, or the name of a GX Works3 CSV file ([labels.md](labels.md))",
     .doc_type = "array or string", .holds = S::Label, .also = S::LabelsFile},
    {.section = S::Station, .key = "structures", .flag = "", .type = T::Array, .default_text = "none",
     .help = "structure types of the global labels ([labels.md](labels.md))", .holds = S::Structure, .also = S::LabelsFile},

    // --- "labels", "structures" (label_config.cpp; [labels.md](labels.md)) ------------------------------------------------
    {.section = S::Label, .key = "name", .flag = "", .type = T::String, .default_text = "required",
     .help = "letters, digits, `_` (and non-ASCII letters), not starting with a digit, not a device name (`D100`, "
             "`X1F`, `K4M0`); case-sensitive",
     .required = true},
    {.section = S::Label, .key = "type", .flag = "", .type = T::String, .default_text = "required",
     .help = "a type below, optionally with an array part `(0..n)`, `(0..n,0..m)`, `(0..n,0..m,0..k)` (lower bound 0)",
     .required = true},
    {.section = S::Label, .key = "device", .flag = "", .type = T::String, .default_text = "the label area",
     .help = "the device the label is assigned to; without it the label lives in the CPU's label area"},
    {.section = S::Label, .key = "dims", .flag = "", .type = T::Array, .default_text = "—",
     .help = "the array sizes instead: `[20]`, `[2, 20]`, 1–3 dimensions of 1–65536 — not together with an array "
             "part in `type`"},
    {.section = S::Label, .key = "external", .flag = "", .type = T::Boolean, .default_text = "`true`",
     .help = "\"Access from External Device\"; **default `true` in slmp-sim** (GX Works3's default is off — a "
             "simulator is there to be read). `false`: SLMP answers 40C0, as a real CPU does"},
    {.section = S::Label, .key = "comment", .flag = "", .type = T::String, .default_text = "—",
     .help = "allowed on labels, structures and members; ignored"},
    {.section = S::Structure, .key = "name", .flag = "", .type = T::String, .default_text = "required",
     .help = "a structure type's name, the `type` of labels and members of it. A structure may use only structures "
             "declared before it",
     .required = true},
    {.section = S::Structure, .key = "members", .flag = "", .type = T::Array, .default_text = "required",
     .help = "its members (below)", .required = true, .holds = S::Member},
    {.section = S::Structure, .key = "comment", .flag = "", .type = T::String, .default_text = "—",
     .help = "ignored"},
    {.section = S::Member, .key = "name", .flag = "", .type = T::String, .default_text = "required",
     .help = "as a label's", .required = true},
    {.section = S::Member, .key = "type", .flag = "", .type = T::String, .default_text = "required",
     .help = "as a label's", .required = true},
    {.section = S::Member, .key = "dims", .flag = "", .type = T::Array, .default_text = "—", .help = "as a label's"},
    {.section = S::Member, .key = "comment", .flag = "", .type = T::String, .default_text = "—", .help = "ignored"},

    {.section = S::Station, .key = "state_dir", .flag = "state-dir", .type = T::String, .flag_arg = F::Text,
     .default_text = "none", .help = "keep device memory here across restarts (see docs/cpu-runtime.md)",
     .doc = "keep device memory here (`--state-dir`); nothing touches disk without it; file drives without a "
            "folder of their own live in `<state_dir>/drives/<n>`",
     .doc_table = "cpu"},
    {.section = S::Station, .key = "drives", .flag = "drive", .type = T::Object, .flag_arg = F::TextList,
     .default_text = "the family's drives, in memory",
     .help = "N=DIR: serve file drive N from the folder DIR; repeatable (docs/files.md)",
     .doc = "file drives of CPU No.1 (1810–182A): a host folder (must exist), capacity in bytes, the SD LOCK "
            "switch, card inserted, file passwords; `--drive N=DIR` (repeatable) sets a folder and wins "
            "([files.md](files.md))",
     .doc_type = "`{\"4\": {\"dir\": \"plc-data\", \"capacity\": 4194304, \"write_protect\": false, \"present\": "
                 "true, \"passwords\": {\"LINE.CSV\": \"secret1\"}}}`",
     .doc_table = "cpu", .holds = S::Drive},
    {.section = S::Drive, .key = "dir", .flag = "", .type = T::String, .default_text = "memory",
     .help = "the host folder that holds the drive's files (must exist)"},
    {.section = S::Drive, .key = "capacity", .flag = "", .type = T::Integer, .max = 1099511627776.0,
     .default_text = "the family's", .help = "capacity in bytes", .plain_range = true},
    {.section = S::Drive, .key = "write_protect", .flag = "", .type = T::Boolean, .default_text = "the family's",
     .help = "the SD card's LOCK switch"},
    {.section = S::Drive, .key = "present", .flag = "", .type = T::Boolean,
     .default_text = "the family's (`true` with `dir`)", .help = "a card is in the slot"},
    {.section = S::Drive, .key = "passwords", .flag = "", .type = T::Object, .default_text = "none",
     .help = "file passwords by file name: `{\"LINE.CSV\": \"secret1\"}`"},
    {.section = S::Station, .key = "timing", .flag = "", .type = T::Object, .default_text = "`{\"mode\": \"instant\"}`",
     .help = "when answers leave ([below](#timing-timing), [timing.md](timing.md))", .doc_table = "cpu", .holds = S::Timing},
    {.section = S::Station, .key = "clock_speed", .flag = "clock-speed", .type = T::Number, .flag_arg = F::Real,
     .min = 0.01, .max = 1000, .default_text = "1",
     .help = "run the CPU's clock (scan, timers, scenarios) this many times faster than real time (default 1)",
     .fix = "use a factor from 0.01 to 1000 (default 1: real time)",
     .doc = "the CPU's clock runs this many times faster than real time, 0.01–1000 (`--clock-speed`; "
            "[scenarios.md](scenarios.md#clock))",
     .doc_table = "cpu"},
    {.section = S::Station, .key = "snapshot_interval_s", .flag = "", .type = T::Number, .min = 0, .max = 86400,
     .default_text = "0", .help = "also save every N seconds (0: only at shutdown and on SIGUSR1)",
     .fix = "use 0 (only at shutdown) to 86400 seconds", .doc_table = "cpu"},
    {.section = S::Station, .key = "restore", .flag = "", .type = T::Choice, .choices = "latched|all",
     .default_text = "\"latched\"",
     .help = "what a restart brings back: latched devices only (a power cycle) or everything saved",
     .fix = "use \"latched\" or \"all\"", .doc_table = "cpu", .noun = "restore mode"},

    // --- "ports": [ {...} ] ------------------------------------------------------------------------------------------
    {.section = S::Port, .key = "transport", .flag = "", .type = T::Choice, .choices = "tcp|udp",
     .default_text = "required", .help = "", .fix = "use \"tcp\" or \"udp\"", .required = true, .noun = "transport"},
    {.section = S::Port, .key = "port", .flag = "", .type = T::Integer, .min = 0, .max = 65535,
     .default_text = "required", .help = "`0` = any free port (read it back from `--ready-file`)",
     .fix = "use 0-65535 (0 = any free port)", .required = true},
    {.section = S::Port, .key = "data_code", .flag = "data-code", .type = T::Choice, .flag_arg = F::Text,
     .choices = "binary|ascii|auto", .default_text = "\"auto\"",
     .help = "binary, ascii or auto (detect per message; default)",
     .doc = "a message in the other code is ignored (no answer), as a real port set to one code does "
            "(`--data-code` sets every port)"},
    {.section = S::Port, .key = "max_connections", .flag = "max-connections", .type = T::Integer,
     .flag_arg = F::Unsigned, .min = 1, .max = 4096,
     .default_text = "the profile's (16 on iQ-R, Q, L; 8 on FX5; 56 on RJ71EN71)",
     .help = "TCP clients served at once per port (default: the profile's, 16 on iQ-R/Q/L, 8 on FX5; 1 = one iQ-R connection entry)",
     .fix = "use 1 to 4096; 1 reproduces an iQ-R built-in port",
     .doc = "TCP clients at once; at the limit the listening socket is closed, so further clients get *connection "
            "refused*. See [Connections per port](#connections-per-port)",
     .doc_type = "number ≥ 1"},
    {.section = S::Port, .key = "idle_timeout_ms", .flag = "idle-timeout", .type = T::Integer, .flag_arg = F::Real,
     .min = 0, .max = 86400000, .default_text = "300000",
     .help = "close a TCP connection silent for this many seconds (default 300; 0 = never)",
     .fix = "use 0 (never) to 86400000 ms (default 300000)",
     .doc = "close a TCP connection silent this long; `0` = never (`--idle-timeout` in seconds)",
     .flag_scale = 1000, .flag_fix = "use 0 (never) to 86400 seconds"},
    {.section = S::Port, .key = "partial_frame_timeout_ms", .flag = "partial-frame-timeout", .type = T::Integer,
     .flag_arg = F::Real, .min = 0, .max = 86400000, .default_text = "5000",
     .help = "close a TCP connection whose started frame is not whole after this many seconds (default 5; 0 = never)",
     .fix = "use 0 (never) to 86400000 ms (default 5000)",
     .doc = "close a TCP connection whose started frame is not whole this long after its first byte (logged as a "
            "warning); `0` = never. Bytes that trickle in do not extend it, so half-sent headers cannot hold "
            "connection slots (a slowloris client) for the idle timeout. While the server waits to write answers "
            "a slow client has not read yet, it reads nothing, so this timeout waits too and counts again from the "
            "write's end (the idle timeout does not wait)",
     .flag_scale = 1000, .flag_fix = "use 0 (never) to 86400 seconds"},
    {.section = S::Port, .key = "max_connections_per_address", .flag = "max-connections-per-address",
     .type = T::Integer, .flag_arg = F::Unsigned, .min = 0, .max = 4096, .default_text = "0",
     .help = "TCP clients served at once per port from one IP address (default 0 = no limit)",
     .fix = "use 0 (no limit) to 4096",
     .doc = "TCP clients at once from one IP address; a new connection from an address at its limit is accepted "
            "and closed at once (logged), while other addresses are served; `0` = no limit. A simulator's guard: "
            "real ports have no such setting"},
    {.section = S::Port, .key = "remote_password", .flag = "", .type = T::Boolean, .default_text = "`true`",
     .help = "the CPU's remote password (`cpu.password`) locks this port's connections. As on a real module the "
             "password is enabled per port: a port with `false` is served without Unlock (there, 1630 answers "
             "0000 and 1631 C810, as on a CPU without a password)"},
    {.section = S::Port, .key = "online_change", .flag = "", .type = T::Boolean,
     .default_text = "the profile's (`true`)",
     .help = "writes served while the CPU is in RUN. With `false`, a write request (every command the command "
             "table marks as writing) while the CPU is in RUN answers the profile's "
             "`end_codes.online_change_refused` (0055, the L/Q E71 code) and changes nothing; reads, and writes "
             "in STOP/PAUSE, are served"},
    {.section = S::Port, .key = "network", .flag = "network-no", .type = T::Integer, .flag_arg = F::Unsigned,
     .min = 1, .max = 239, .default_text = "not set",
     .help = "the station's network No. (1-239) on every port, with --station-no; requests to it are served as the own station",
     .doc = "the station's network No. (1–239), given together with `station`, as set on the real module: a "
            "request addressed to them is served as the own station, besides 00/FF; another station gets 4A02, "
            "another network 4A01 ([end-codes.md](end-codes.md#own-network-and-station-numbers))",
     .own_check = true},
    {.section = S::Port, .key = "station", .flag = "station-no", .type = T::Integer, .flag_arg = F::Unsigned,
     .min = 1, .max = 120, .default_text = "not set",
     .help = "the station's station No. (1-120) on every port, with --network-no",
     .doc = "the station's station No. (1–120), given together with `network`", .own_check = true},

    // --- "http" -----------------------------------------------------------------------------------------------------
    {.section = S::Http, .key = "enabled", .flag = "no-http", .type = T::Boolean, .default_text = "`true`",
     .help = "serve no HTTP API, metrics or web monitor",
     .doc = "`false` serves no HTTP at all (`--no-http`)"},
    {.section = S::Http, .key = "port", .flag = "http-port", .type = T::Integer, .flag_arg = F::Unsigned, .min = 0,
     .max = 65535, .default_text = "8080",
     .help = "HTTP API, metrics and web monitor port; 0 = any free port (default 8080)",
     .fix = "use 0-65535 (0 = any free port)",
     .doc = "`0` = any free port; the port is written to the `--ready-file` as `\"http\": N` (`--http-port` turns "
            "HTTP on even when the file turned it off)",
     .flag_fix = "not a port number; use 0-65535 (0 = any free port)"},
    {.section = S::Http, .key = "bind", .flag = "http-bind", .type = T::String, .flag_arg = F::Text,
     .default_text = "the SLMP `bind` address", .help = "address for the HTTP port (default: the --bind address)",
     .doc = "listen address of the HTTP port (a plant whose stations bind different addresses: `0.0.0.0`)"},

    // --- "cpu" ------------------------------------------------------------------------------------------------------
    {.section = S::Cpu, .key = "switch", .flag = "switch", .type = T::Choice, .flag_arg = F::Text,
     .choices = "RUN|STOP", .default_text = "\"RUN\"",
     .help = "the CPU's RUN/STOP switch: RUN (default) or STOP", .doc = "the RUN/STOP switch (`--switch`)"},
    {.section = S::Cpu, .key = "scan_time_ms", .flag = "", .type = T::Integer, .min = 1, .max = 1000,
     .default_text = "10", .help = "time between scans", .fix = "use 1 to 1000 (default 10)", .doc_type = "1–1000"},
    {.section = S::Cpu, .key = "remote_reset", .flag = "", .type = T::Boolean, .default_text = "`false`",
     .help = "allow Remote RESET 1006 (the CPU parameter; off by default as on the real CPU: 4014)",
     .doc_type = "bool"},
    {.section = S::Cpu, .key = "output_off_at_stop", .flag = "", .type = T::Boolean, .default_text = "`true`",
     .help = "turn every Y off when the CPU enters STOP", .doc_type = "bool"},
    {.section = S::Cpu, .key = "password", .flag = "", .type = T::String, .default_text = "none",
     .help = "remote password; length per the profile's `remote_password_length`"},
    {.section = S::Cpu, .key = "password_lockout", .flag = "", .type = T::Object, .default_text = "10, 60",
     .help = "wrong passwords in a row before C815, and for how long; `attempts: 0` never locks out",
     .doc_type = "`{\"attempts\": N, \"seconds\": S}`", .holds = S::Lockout},
    {.section = S::Lockout, .key = "attempts", .flag = "", .type = T::Integer, .max = 1000, .default_text = "10",
     .help = "wrong passwords in a row before C815; `0` never locks out", .plain_range = true},
    {.section = S::Lockout, .key = "seconds", .flag = "", .type = T::Integer, .max = 86400, .default_text = "60",
     .help = "how long the lock-out lasts", .plain_range = true},
    {.section = S::Cpu, .key = "system_protect", .flag = "", .type = T::Boolean, .default_text = "`false`",
     .help = "the CPU's system protect (security key / write protection): on every port, writes and remote "
             "operations (1001–1006) answer the profile's `end_codes.system_protect` (4004) and change nothing; "
             "reads and the password's 1630/1631 are served"},
    {.section = S::Cpu, .key = "latch", .flag = "", .type = T::Object, .default_text = "none",
     .help = "latch ranges per area (numbers, or addresses such as `\"W1F\"` for hex devices); L, R and ZR are "
             "always kept",
     .doc_type = "`{\"D\": [first, last]}` or `{\"D\": [[a, b], [c, d]]}`"},
    {.section = S::Cpu, .key = "timers", .flag = "", .type = T::Array, .default_text = "none",
     .help = "timers that time while their coil is on (T, ST, LT, LST; `base_ms` 0.001–1000, default 100, LT/LST "
             "0.001)",
     .doc_type = "`[{\"device\": \"T0\", \"points\": 1, \"preset\": 20, \"base_ms\": 100}]`", .holds = S::Timer},
    {.section = S::Timer, .key = "device", .flag = "", .type = T::String, .default_text = "required",
     .help = "the first device: T, ST, LT or LST for a timer, C or LC for a counter (`\"T0\"`, `\"C10\"`)",
     .required = true, .also = S::Counter},
    {.section = S::Timer, .key = "points", .flag = "", .type = T::Integer, .max = 0x7FFFFFFF, .default_text = "1",
     .help = "how many devices from it", .also = S::Counter, .plain_range = true},
    {.section = S::Timer, .key = "preset", .flag = "", .type = T::Integer, .default_text = "required",
     .help = "the set value: up to 32767, on LT, LST and LC up to 4294967295", .required = true, .own_check = true,
     .also = S::Counter},
    {.section = S::Timer, .key = "base_ms", .flag = "", .type = T::Number, .min = 0.001, .max = 1000,
     .default_text = "100 (LT, LST: 0.001)", .help = "a timer's time base in ms",
     .fix = "use 0.001 to 1000 (100 low-speed, 10 high-speed, 1)"},
    {.section = S::Cpu, .key = "counters", .flag = "", .type = T::Array, .default_text = "none",
     .help = "counters that count coil rising edges (C, LC)",
     .doc_type = "`[{\"device\": \"C0\", \"points\": 1, \"preset\": 5}]`", .holds = S::Counter},
    {.section = S::Cpu, .key = "program", .flag = "", .type = T::Object, .default_text = "none",
     .help = "the PLC program the CPU runs scan by scan (`--program FILE` sets `file`); every key: "
             "[program.md](program.md#configuration)",
     .doc_type = "`{\"file\": \"line1.csv\", \"operation_error\": \"stop\", \"wdt_ms\": 200, ...}`", .holds = S::Program},
    {.section = S::Cpu, .key = "error", .flag = "", .type = T::Object, .default_text = "none",
     .help = "a CPU error present from the start (SD0/SM0; `stop: true` keeps the CPU in STOP until a Remote "
             "RESET)",
     .doc_type = "`{\"code\": \"1900\", \"stop\": false}`", .holds = S::CpuError},
    {.section = S::CpuError, .key = "code", .flag = "", .type = T::String, .default_text = "required",
     .help = "the error code, 4 hex digits (`\"1900\"`)", .required = true},
    {.section = S::CpuError, .key = "stop", .flag = "", .type = T::Boolean, .default_text = "`false`",
     .help = "`true`: a stop error, the CPU stays in STOP until a Remote RESET"},

    // --- "cpu": {"program": {...}} -------------------------------------------------------------------------------------
    {.section = S::Program, .key = "file", .flag = "program", .type = T::String, .flag_arg = F::Text,
     .default_text = "— (required)",
     .help = "run this PLC program (GX Works2/3 CSV list or text instruction list) scan by scan (docs/program.md)",
     .doc = "the program; relative paths start at the configuration file's folder. `--program FILE` sets it.",
     .required = true},
    {.section = S::Program, .key = "comments", .flag = "", .type = T::String, .default_text = "none",
     .help = "device comments (GX Works CSV); relative paths as `file`", .doc = "device comment file"},
    {.section = S::Program, .key = "operation_error", .flag = "", .type = T::Choice, .choices = "stop|continue",
     .default_text = "\"stop\"", .help = "what an operation error does: stop the CPU or continue the scan",
     .fix = "use \"stop\" or \"continue\"",
     .doc = "`stop`: an operation error ends the scan and stops the CPU (stop error, SD203 = 0x0042, Y off, Remote "
            "RUN answers C05F until RESET); `continue`: SM0/SM1 (and SM56 on Q/L) and SD0 are set, the failing "
            "instruction does nothing, execution goes on; SM50 (error reset) clears them at END ([cpu-runtime.md](cpu-runtime.md#remote-operations-and-their-end-codes): a CPU's built-in port refuses 1617)", .noun = "mode"},
    {.section = S::Program, .key = "wdt_ms", .flag = "", .type = T::Integer, .min = 10, .max = 2000,
     .default_text = "200", .help = "the scan's watchdog time, in steps of 10 ms",
     .fix = "use 10 to 2000 in steps of 10 (default 200)",
     .doc = "watchdog, 10–2000 in steps of 10, on the **modelled** execution time (below)",
     .below_min = "out of range", .plain_range = true, .step = 10},
    {.section = S::Program, .key = "timer_limit", .flag = "", .type = T::Object,
     .default_text = "`{\"low_ms\": 100, \"high_ms\": 10}`",
     .help = "the time bases of `OUT T` and `OUTH T` (below)", .holds = S::TimerLimit},
    {.section = S::Program, .key = "output_mode_at_run", .flag = "", .type = T::Choice,
     .choices = "previous|recalculate", .default_text = "\"previous\"",
     .help = "the outputs when STOP turns to RUN: as before STOP, or as the first scan computes them",
     .fix = "use \"previous\" or \"recalculate\"",
     .doc = "at STOP→RUN: `previous` puts back the Y image saved at STOP before scan 1; `recalculate` leaves Y off "
            "until the program writes them. A Remote RUN with a clear mode clears the saved image too.", .noun = "mode"},
    {.section = S::Program, .key = "max_steps_per_scan", .flag = "", .type = T::Integer, .min = 1000,
     .max = 1'000'000'000, .default_text = "10000000",
     .help = "a scan that runs more steps (a loop that does not end) is a watchdog error",
     .fix = "use 1000 to 1000000000 (default 10000000)",
     .doc = "host guard for loops whose modelled time is tiny: more executed instructions in one scan is a "
            "watchdog error"},
    {.section = S::Program, .key = "allow_double_timer_coils", .flag = "", .type = T::Boolean,
     .default_text = "`false`", .help = "allow two OUT coils of one timer (refused at load otherwise)",
     .doc = "a timer or counter driven by two `OUT` steps is a load error unless set"},
    {.section = S::TimerLimit, .key = "low_ms", .flag = "", .type = T::Integer, .min = 1, .max = 1000,
     .default_text = "100", .help = "time base of `OUT T`", .fix = "use 1 to 1000 (default 100)"},
    {.section = S::TimerLimit, .key = "high_ms", .flag = "", .type = T::Integer, .min = 1, .max = 100,
     .default_text = "10", .help = "time base of `OUTH T`", .fix = "use 1 to 100 (default 10)"},

    // --- "timing" ----------------------------------------------------------------------------------------------------
    {.section = S::Timing, .key = "mode", .flag = "timing", .type = T::Choice, .flag_arg = F::Text,
     .choices = "instant|end_of_scan|model", .default_text = "\"instant\"",
     .help = "when answers leave: instant (default), end_of_scan or model (docs/timing.md)",
     .fix = "use \"instant\" (default), \"end_of_scan\" or \"model\"", .noun = "timing mode"},
    {.section = S::Timing, .key = "ke_ms", .flag = "", .type = T::Number, .min = 0, .max = 60000,
     .default_text = "the profile's", .help = "model: Ke, the fixed part of a response (both codes)",
     .fix = "use 0 to 60000 ms", .also = S::ProfileTiming},
    {.section = S::Timing, .key = "ke_ascii_ms", .flag = "", .type = T::Number, .min = 0, .max = 60000,
     .default_text = "the profile's", .help = "model: Ke for ASCII frames", .fix = "use 0 to 60000 ms", .also = S::ProfileTiming},
    {.section = S::Timing, .key = "kdt_ms", .flag = "", .type = T::Number, .min = 0, .max = 100,
     .default_text = "the profile's", .help = "model: Kdt, the time a device point adds", .fix = "use 0 to 100 ms", .also = S::ProfileTiming},
    {.section = S::Timing, .key = "kdt_ascii_ms", .flag = "", .type = T::Number, .min = 0, .max = 100,
     .default_text = "the profile's", .help = "model: Kdt for ASCII frames", .fix = "use 0 to 100 ms", .also = S::ProfileTiming},
    {.section = S::Timing, .key = "scan_wait", .flag = "", .type = T::Boolean, .default_text = "the profile's",
     .help = "model: the answer also waits for the END of the scan", .also = S::ProfileTiming},
    {.section = S::Timing, .key = "jitter", .flag = "", .type = T::Number, .min = 0, .max = 1, .default_text = "0",
     .help = "model: ± this fraction of the modelled time, at random",
     .fix = "use 0 (none) to 1 (± the whole modelled time), e.g. 0.1"},
    {.section = S::Timing, .key = "seed", .flag = "", .type = T::Integer, .min = 0, .max = kAnyUnsigned,
     .default_text = "1", .help = "model: the jitter's random stream: the same seed, the same times",
     .plain_range = true},

    // --- a CPU profile (config/profiles/*.json; profile_loader.cpp) -----------------------------------------------------
    {.section = S::Profile, .key = "name", .flag = "", .type = T::String, .default_text = "required", .help = "the profile id (the `--profile` name of a built-in one is its file name)", .required = true},
    {.section = S::Profile, .key = "description", .flag = "", .type = T::String, .help = "a line about it, for `--list-profiles`; an extending profile gives its own"},
    {.section = S::Profile, .key = "extends", .flag = "", .type = T::String, .help = "the base profile (a built-in name, or for a file a path relative to it); the profile gives only what differs"},
    {.section = S::Profile, .key = "type_name", .flag = "", .type = T::String, .default_text = "required", .help = "what Read Type Name (0101) answers: up to 16 characters", .required = true},
    {.section = S::Profile, .key = "model_code", .flag = "", .type = T::String, .default_text = "required", .help = "what Read Type Name (0101) answers: a 4-hex-digit code", .required = true},
    {.section = S::Profile, .key = "family", .flag = "", .type = T::Choice, .choices = "iQ-R|QnU|L|QJ71E71|iQ-F", .default_text = "required", .help = "the command table says which commands each family serves (QnU/L built-in ports refuse 0101, 0406/1406, 0619, 0613/1613; iQ-F refuses 0801/0802, 0613/1613 — real-CPU measurements)", .required = true},
    {.section = S::Profile, .key = "frame_4e", .flag = "", .type = T::String, .default_text = "required", .help = "how a 4E request is treated: `answer`, `silence` (no response), `close` (close the TCP connection) or an end code such as `\"C059\"`", .required = true},
    {.section = S::Profile, .key = "frame_1e", .flag = "", .type = T::Object, .help = "`{\"pc_type\": \"0041\"}`: the port serves the A-compatible 1E frame, binary and ASCII, and 1E PC type read answers the low byte of `pc_type`; without it 1E bytes are no frame there (skipped unanswered, as on an iQ-R built-in port). [frames.md](frames.md)", .holds = S::Frame1E},
    {.section = S::Frame1E, .key = "pc_type", .flag = "", .type = T::String, .default_text = "required",
     .help = "1E PC type read's answer, one byte as 4 hex digits (`\"0041\"`)", .required = true},
    {.section = S::Profile, .key = "station_extended_frame", .flag = "", .type = T::Boolean, .default_text = "`false`", .help = "`true`: the port serves the station-number-extended frame (`68 00`, binary; CC-Link IE TSN modules, profile `RJ71GN11-T2`); without it those bytes are no frame there. [frames.md](frames.md)"},
    {.section = S::Profile, .key = "relays", .flag = "", .type = T::Boolean, .default_text = "`false`", .help = "`true`: the port is a network/Ethernet module's (RJ71EN71, QJ71E71-100, RJ71GN11-T2), which relays a request naming another network/station of the plant to that station's CPU; a CPU's built-in port (`false`) reaches only its own station. [plants.md](plants.md#networks-and-routes)"},
    {.section = S::Profile, .key = "node_commands", .flag = "", .type = T::Boolean, .default_text = "`false`", .help = "`true`: the port is an SLMP-compatible device's (the CC-Link Partner Association's manual, §3.12–3.14), which serves the node commands 0E30–0E53 (node search, IP address set, parameter get/set, status read); the Mitsubishi CPUs and modules of the built-in profiles are their clients and answer C059. [nodes.md](nodes.md)"},
    {.section = S::Profile, .key = "pipeline", .flag = "", .type = T::Object, .default_text = "no limit", .help = "`{\"buffer\": N, \"over_limit\": \"CEE0\"}`: commands per connection — of a pipelined burst, 1 + N ÷ (open connections) requests are served, the rest get `over_limit` (an end code, `silence` or `close`; default CEE0). [end-codes.md](end-codes.md#commands-per-connection-pipelining-limit)", .holds = S::Pipeline},
    {.section = S::Pipeline, .key = "buffer", .flag = "", .type = T::Integer, .max = 65535, .default_text = "required",
     .help = "N of 1 + N ÷ (open connections)", .required = true, .plain_range = true},
    {.section = S::Pipeline, .key = "over_limit", .flag = "", .type = T::String, .default_text = "\"CEE0\"",
     .help = "what a request over the limit gets: an end code, `silence` or `close`"},
    {.section = S::Profile, .key = "iqr_subcommands", .flag = "", .type = T::String, .default_text = "required", .help = "the same choice as `frame_4e` for device commands in the iQ-R form (00□2/00□3)", .required = true},
    {.section = S::Profile, .key = "unsupported_commands", .flag = "", .type = T::Array, .default_text = "none", .help = "further commands this port refuses with `end_codes.not_supported`, beyond what its family refuses"},
    {.section = S::Profile, .key = "end_codes", .flag = "", .type = T::Object, .default_text = "required", .help = "the end codes of the port's refusals (each below)", .required = true, .holds = S::EndCodes},
    {.section = S::EndCodes, .key = "not_supported", .flag = "", .type = T::String, .default_text = "required",
     .help = "a command this port does not serve (C059)", .required = true},
    {.section = S::EndCodes, .key = "out_of_range", .flag = "", .type = T::String, .default_text = "required",
     .help = "a device range past the area (4031 iQ-R, C056 Q/L)", .required = true},
    {.section = S::EndCodes, .key = "not_accessible", .flag = "", .type = T::String, .default_text = "required",
     .help = "a device this port may not write (4030)", .required = true},
    {.section = S::EndCodes, .key = "unknown_device", .flag = "", .type = T::String, .default_text = "required",
     .help = "a device code the CPU does not have (C05B)", .required = true},
    {.section = S::EndCodes, .key = "bad_unit", .flag = "", .type = T::String, .default_text = "required",
     .help = "a request for a module or CPU that is not there (C05C)", .required = true},
    {.section = S::EndCodes, .key = "online_change_refused", .flag = "", .type = T::String, .default_text = "\"0055\"",
     .help = "a write in RUN on a port without online change (default 0055)"},
    {.section = S::EndCodes, .key = "system_protect", .flag = "", .type = T::String, .default_text = "\"4004\"",
     .help = "a write or remote operation under system protect (default 4004)"},
    {.section = S::Profile, .key = "online_change", .flag = "", .type = T::Boolean, .default_text = "`true`", .help = "the ports' default for `online_change`"},
    {.section = S::Profile, .key = "limits", .flag = "", .type = T::Object, .default_text = "required", .help = "the port's limits per request (each below): a limit of points `{\"max\": N, \"end_code\": \"C051\"}`, or per request form `{\"q\": N, \"iqr\": N, \"end_code\": \"C054\"}` — the limit for the Q form and the iQ-R form", .required = true, .holds = S::Limits},
    {.section = S::Limits, .key = "batch_words", .flag = "", .type = T::Object, .default_text = "required",
     .help = "0401/1401 in word units: points", .doc_type = "`{\"max\": N, \"end_code\": \"C051\"}`", .required = true, .holds = S::PointLimit},
    {.section = S::Limits, .key = "batch_bits_binary", .flag = "", .type = T::Object, .default_text = "required",
     .help = "0401/1401 in bit units, binary code: points", .doc_type = "`{\"max\": N, \"end_code\": \"C051\"}`", .required = true, .holds = S::PointLimit},
    {.section = S::Limits, .key = "batch_bits_ascii", .flag = "", .type = T::Object, .default_text = "required",
     .help = "0401/1401 in bit units, ASCII code: points", .doc_type = "`{\"max\": N, \"end_code\": \"C051\"}`", .required = true, .holds = S::PointLimit},
    {.section = S::Limits, .key = "loopback_bytes", .flag = "", .type = T::Integer, .max = 65535, .default_text = "required",
     .help = "bytes of a loopback test (0619)", .required = true, .plain_range = true},
    {.section = S::Limits, .key = "random_read_points", .flag = "", .type = T::Object, .default_text = "required",
     .help = "0403: word + double-word points", .doc_type = "`{\"q\": N, \"iqr\": N, \"end_code\": \"C054\"}`", .required = true, .holds = S::FormLimit},
    {.section = S::Limits, .key = "random_write_weight", .flag = "", .type = T::Object, .default_text = "required",
     .help = "1402 in word units: 12 × words + 14 × double words", .doc_type = "`{\"q\": N, \"iqr\": N, \"end_code\": \"C054\"}`", .required = true, .holds = S::FormLimit},
    {.section = S::Limits, .key = "random_write_bits", .flag = "", .type = T::Object, .default_text = "required",
     .help = "1402 in bit units: points", .doc_type = "`{\"q\": N, \"iqr\": N, \"end_code\": \"C054\"}`", .required = true, .holds = S::FormLimit},
    {.section = S::Limits, .key = "monitor_points", .flag = "", .type = T::Object, .default_text = "required",
     .help = "0801: word + double-word points", .doc_type = "`{\"q\": N, \"iqr\": N, \"end_code\": \"C054\"}`", .required = true, .holds = S::FormLimit},
    {.section = S::Limits, .key = "block_count", .flag = "", .type = T::Object, .default_text = "required",
     .help = "0406/1406: word blocks + bit blocks", .doc_type = "`{\"q\": N, \"iqr\": N, \"end_code\": \"C054\"}`", .required = true, .holds = S::FormLimit},
    {.section = S::Limits, .key = "block_points", .flag = "", .type = T::Object, .default_text = "required",
     .help = "0406/1406: total points (1406 adds 4 or 9 per block)", .doc_type = "`{\"max\": N, \"end_code\": \"C051\"}`", .required = true, .holds = S::PointLimit},
    {.section = S::Limits, .key = "extended_over_limit_code", .flag = "", .type = T::String, .default_text = "—",
     .help = "what an over-limit random read, random write or monitor registration with extended devices (subcommand 008x) answers instead of the limit's own code (QJ71E71-100: 4080)"},
    {.section = S::PointLimit, .key = "max", .flag = "", .type = T::Integer, .max = 65535, .default_text = "required",
     .help = "the most points", .required = true, .plain_range = true},
    {.section = S::FormLimit, .key = "q", .flag = "", .type = T::Integer, .max = 65535, .default_text = "required",
     .help = "the most points in the Q form (00□0/00□1)", .required = true, .plain_range = true},
    {.section = S::FormLimit, .key = "iqr", .flag = "", .type = T::Integer, .max = 65535, .default_text = "required",
     .help = "the most points in the iQ-R form (00□2/00□3)", .required = true, .plain_range = true},
    {.section = S::PointLimit, .key = "end_code", .flag = "", .type = T::String, .default_text = "required",
     .help = "what a request over the limit answers", .required = true, .also = S::FormLimit},
    {.section = S::Profile, .key = "mixed_block_write", .flag = "", .type = T::String, .default_text = "required", .help = "1406 with word and bit blocks: `answer` or an end code (`\"C05B\"` R08CPU)", .required = true},
    {.section = S::Profile, .key = "station_buffer_words", .flag = "", .type = T::Integer, .max = 0x7FFFFFFF, .help = "0613/1613 reach a buffer of this many words of the port's own (QJ71E71-100) instead of the CPU buffer memory", .plain_range = true},
    {.section = S::Profile, .key = "device_sizes", .flag = "", .type = T::Object, .default_text = "required", .help = "points per area (areas left out do not exist on this CPU)", .required = true},
    {.section = S::Profile, .key = "start_only_range_check", .flag = "", .type = T::Array, .default_text = "required", .help = "areas where only the start device is range-checked (iQ-R: `R`, `ZR`)", .required = true},
    {.section = S::Profile, .key = "read_only_devices", .flag = "", .type = T::Array, .default_text = "required", .help = "areas that cannot be written over this port (`S`: 4030)", .required = true},
    {.section = S::Profile, .key = "size_registers", .flag = "", .type = T::Array, .default_text = "required", .help = "`{\"device\": \"D\", \"sd\": 280, \"bits\": 32}`: the SD registers that publish each size", .required = true, .holds = S::SizeRegister},
    {.section = S::SizeRegister, .key = "device", .flag = "", .type = T::String, .default_text = "required",
     .help = "the device area whose size it publishes", .required = true},
    {.section = S::SizeRegister, .key = "sd", .flag = "", .type = T::Integer, .max = 0xFFFF, .default_text = "required",
     .help = "the SD register's number", .required = true, .plain_range = true},
    {.section = S::SizeRegister, .key = "bits", .flag = "", .type = T::Integer, .max = 32, .default_text = "required",
     .help = "16 or 32 (a pair of registers, low word first)", .required = true, .plain_range = true},
    {.section = S::Profile, .key = "zr_ascii_hex", .flag = "", .type = T::Boolean, .default_text = "required", .help = "`true` to number ZR in hexadecimal in ASCII frames (the manuals' form); iQ-R CPUs use decimal", .required = true},
    {.section = S::Profile, .key = "max_connections", .flag = "", .type = T::Integer, .min = 1, .max = 4096, .default_text = "64", .help = "the ports' default `max_connections`, the CPU's connection count ([Connections per port](#connections-per-port))", .fix = "write the CPU's connection count, e.g. 16"},
    {.section = S::Profile, .key = "manual_vs_hardware", .flag = "", .type = T::Object, .help = "where the manuals and real CPUs differ, keyed by topic: `{\"mixed_block_write\": {\"what\": \"1406 with word and bit blocks together\", \"manual\": \"served\", \"hardware\": \"C05B (R08CPU)\", \"follows\": \"hardware\"}}`; `follows` is `manual` or `hardware`. A profile that extends another changes one topic key by key. Listed in [compatibility.md](compatibility.md#where-the-manuals-and-real-cpus-differ)", .holds = S::Difference},
    {.section = S::Difference, .key = "what", .flag = "", .type = T::String, .default_text = "required",
     .help = "the behaviour, in a few words", .required = true},
    {.section = S::Difference, .key = "manual", .flag = "", .type = T::String, .default_text = "required",
     .help = "what the manuals say", .required = true},
    {.section = S::Difference, .key = "hardware", .flag = "", .type = T::String, .default_text = "required",
     .help = "what the real CPU does", .required = true},
    {.section = S::Difference, .key = "follows", .flag = "", .type = T::Choice, .choices = "manual|hardware",
     .default_text = "required", .help = "which of the two the profile does", .required = true},
    {.section = S::Profile, .key = "xy_radix", .flag = "", .type = T::Integer, .max = 16, .default_text = "16", .help = "`8` numbers X and Y (and DX/DY) in octal, as an iQ-F CPU does ([X/Y numbering](#xy-numbering-fx5-octal))", .plain_range = true},
    {.section = S::Profile, .key = "timing", .flag = "", .type = T::Object, .default_text = "see timing.md", .help = "`{\"ke_ms\": 3.9, \"ke_ascii_ms\": 3.9, \"kdt_ms\": 0.003, \"kdt_ascii_ms\": 0.0045, \"scan_wait\": true}`: the response-time model's constants for this CPU (sources in [timing.md](timing.md))", .holds = S::ProfileTiming},
    {.section = S::Profile, .key = "file_drives", .flag = "", .type = T::Object, .default_text = "none", .help = "the CPU's file drives, keyed by number (the keys below): `{\"2\": {\"kind\": \"sd_card\", \"capacity\": 8388608, \"present\": true, \"write_protect\": false}, \"1\": {\"kind\": \"device_label_memory\", \"alias_of\": 3}}`; `present` and `write_protect` are the defaults the configuration's `drives` may change. A profile that `extends` another changes one drive key by key and removes one with `null`. Without drives the port refuses the file commands (C059) ([files.md](files.md#drives-per-family))", .holds = S::FileDrive},
    // "file_drives": {"2": {...}} (profile_drives.cpp); an alias has only its own two keys.
    {.section = S::FileDrive, .key = "kind", .flag = "", .type = T::Choice,
     .choices = "program_memory|sram_card|sd_card|standard_ram|standard_rom|device_label_memory|data_memory",
     .default_text = "required", .help = "what the drive is",
     .fix = "use program_memory, sram_card, sd_card, standard_ram, standard_rom, device_label_memory or data_memory",
     .required = true, .noun = "drive kind"},
    {.section = S::FileDrive, .key = "capacity", .flag = "", .type = T::Integer, .max = 1099511627776.0,
     .default_text = "required", .help = "bytes of file data the drive holds", .doc_type = "number", .required = true,
     .plain_range = true},
    {.section = S::FileDrive, .key = "present", .flag = "", .type = T::Boolean, .default_text = "`true`",
     .help = "a card is in the slot (the configuration's `drives` may change it)"},
    {.section = S::FileDrive, .key = "write_protect", .flag = "", .type = T::Boolean, .default_text = "`false`",
     .help = "the SD card's LOCK switch (the configuration's `drives` may change it)"},
    {.section = S::DriveAlias, .key = "alias_of", .flag = "", .type = T::Integer, .max = 255, .default_text = "—",
     .help = "the drive this one is another name for (iQ-R drive 1 is drive 3); an alias has only `alias_of` and "
             "`kind` (listed as `\"sd_card\"` when left out), nothing of its own",
     .doc_type = "number", .doc_table = "profile", .required = true, .plain_range = true},
    {.section = S::DriveAlias, .key = "kind", .flag = "", .type = T::Choice,
     .choices = "program_memory|sram_card|sd_card|standard_ram|standard_rom|device_label_memory|data_memory",
     .default_text = "`\"sd_card\"`", .help = "the kind it is listed as",
     .fix = "use program_memory, sram_card, sd_card, standard_ram, standard_rom, device_label_memory or data_memory",
     .noun = "drive kind"},
    {.section = S::Profile, .key = "file_end_codes", .flag = "", .type = T::Object, .default_text = "with `file_drives`", .help = "the end code of each refused file operation — `no_drive`, `bad_name`, `not_found`, `exists`, `not_a_file`, `no_capacity`, `write_protected`, `read_only`, `locked`, `password`, `bad_pointer`, `not_write_mode`, `out_of_range`, `too_many_open`, `host_error`, `run_state` ([end-codes.md](end-codes.md#file-commands-1810182a))"},
    {.section = S::Profile, .key = "remote_password_length", .flag = "", .type = T::Array, .help = "`[min, max]` characters of the remote password: `[4, 4]` Q/L, `[6, 32]` iQ-R and iQ-F; without it 1630/1631 answer `not_supported` and `cpu.password` is refused"},
};
// clang-format on

// Each object: its JSON path (errors and docs), the docs table its rows are
// listed in, and whether it is the value of a key chosen by the user ("drives":
// {"4": {...}}) rather than of a fixed key or an array entry.
struct SectionInfo {
    Section section;
    std::string_view path;
    std::string_view table;
    bool keyed = false;
};

constexpr SectionInfo kSections[] = {
    {S::None, "", ""},
    {S::CommandLine, "(command line)", ""},
    {S::Plant, "(plant)", ""},
    {S::Template, "stations[]", "station"},
    {S::Station, "", "station"},
    {S::Port, "ports[]", "port"},
    {S::Module, "modules[]", "hardware"},
    {S::Network, "networks[]", "hardware"},
    {S::MultiCpu, "cpus[]", "hardware"},
    {S::Redundant, "redundant", "hardware"},
    {S::Multidrop, "multidrop", "hardware"},
    {S::Route, "routes[]", "hardware"},
    {S::NodeSearch, "node_search", "hardware"},
    {S::Drive, "drives.N", "cpu", true},
    {S::Label, "labels[]", "labels"},
    {S::Structure, "structures[]", "labels"},
    {S::Member, "structures[].members[]", "labels"},
    {S::LabelsFile, "(labels file)", ""},
    {S::Http, "http", "http"},
    {S::Cpu, "cpu", "cpu"},
    {S::Lockout, "cpu.password_lockout", "cpu"},
    {S::Timer, "cpu.timers[]", "cpu"},
    {S::Counter, "cpu.counters[]", "cpu"},
    {S::CpuError, "cpu.error", "cpu"},
    {S::Program, "cpu.program", "program"},
    {S::TimerLimit, "cpu.program.timer_limit", "program"},
    {S::Timing, "timing", "timing"},
    {S::Profile, "(profile)", "profile"},
    {S::Frame1E, "frame_1e", "profile"},
    {S::Pipeline, "pipeline", "profile"},
    {S::EndCodes, "end_codes", "profile"},
    {S::Limits, "limits", "profile"},
    {S::PointLimit, "limits.*", "profile"},
    {S::FormLimit, "limits.*", "profile"},
    {S::ProfileTiming, "timing", "profile"},
    {S::Difference, "manual_vs_hardware.TOPIC", "profile", true},
    {S::FileDrive, "file_drives.N", "profile", true},
    {S::DriveAlias, "file_drives.N", "", true},   // alias_of is listed in the profile table; kind is FileDrive's
    {S::SizeRegister, "size_registers[]", "profile"},
};

const SectionInfo& info(Section section) {
    for (const auto& s : kSections)
        if (s.section == section) return s;
    throw std::logic_error("settings table: a section without its SectionInfo");
}

// The docs tables, and the path their keys are written from ("cpu.program":
// the program table writes `wdt_ms`, not `cpu.program.wdt_ms`).
struct DocTable {
    std::string_view name;
    std::string_view base;
};
constexpr DocTable kTables[] = {{"cli", ""},    {"station", ""}, {"port", "ports[]"},      {"hardware", ""},
                                {"labels", ""}, {"http", "http"}, {"cpu", ""},            {"program", "cpu.program"},
                                {"timing", "timing"}, {"profile", ""}};

std::string_view table_of(const Setting& row) {
    if (!row.doc_table.empty()) return row.doc_table;
    return info(row.section).table;
}

bool in_section(const Setting& row, Section section) {
    return section != S::None && !row.key.empty() && (row.section == section || row.also == section);
}

std::string number_text(double v) {
    if (v == std::floor(v) && std::fabs(v) < 1e18) return std::to_string(static_cast<std::int64_t>(v));
    std::ostringstream text;
    text << v;
    return text.str();
}

std::uint64_t whole_max(const Setting& row) {
    return row.max >= kAnyUnsigned ? ~std::uint64_t{0} : static_cast<std::uint64_t>(row.max);
}

std::vector<std::string_view> choices_of(const Setting& row) {
    std::vector<std::string_view> list;
    for (std::string_view rest = row.choices; !rest.empty();) {
        auto bar = rest.find('|');
        list.push_back(rest.substr(0, bar));
        rest = bar == std::string_view::npos ? std::string_view() : rest.substr(bar + 1);
    }
    return list;
}

std::string type_text(const Setting& row) {
    if (!row.doc_type.empty()) return std::string(row.doc_type);
    switch (row.type) {
        case T::String: return "string";
        case T::Integer:
        case T::Number: return "number";
        case T::Boolean: return "boolean";
        case T::Array: return "array";
        case T::Object: return "object";
        case T::None: return "—";
        case T::Choice: {
            std::string text;
            for (auto c : choices_of(row)) text += std::string(text.empty() ? "" : " / ") + "`\"" + std::string(c) + "\"`";
            return text;
        }
    }
    return "";
}

// The key as a table lists it: its path from the table's base; a row that is a
// key of another object of the same table too names both ("cpu.timers[].device",
// "cpu.counters[].device").
std::string key_text(const Setting& row, std::string_view table) {
    std::string_view base;
    for (const auto& t : kTables)
        if (t.name == table) base = t.base;
    auto path_in = [&](Section section) {
        std::string path(info(section).path);
        if (section == S::Plant || section == S::Profile) path.clear();
        if (!base.empty() && path.starts_with(base)) path = path.substr(std::min(path.size(), base.size() + 1));
        return "`" + (path.empty() ? "" : path + ".") + std::string(row.key) + "`";
    };
    auto text = path_in(row.section);
    if (row.also != S::None && info(row.also).table == table && path_in(row.also) != text) text += ", " + path_in(row.also);
    return text;
}

std::string default_cell(const Setting& row) {
    auto d = row.default_text;
    if (d.empty()) return "—";
    // Numbers and quoted JSON values are code; prose is not.
    if (d.front() == '"' || (d.find_first_not_of("0123456789.") == std::string_view::npos))
        return "`" + std::string(d) + "`";
    return std::string(d);
}

std::string flag_cell(const Setting& row) {
    auto f = row.long_flag();
    std::string text = "`--" + std::string(f);
    if (auto comma = row.flag.find(','); comma != std::string_view::npos)
        text += "`, `-" + std::string(row.flag.substr(comma + 1));
    return text + "`";
}

// The --help table's "Key" column: the key's whole path.
std::string key_path(const Setting& row) {
    if (row.key.empty()) return "—";
    std::string path(info(row.section).path);
    if (row.section == S::Station || row.section == S::Plant) path.clear();
    return "`" + (path.empty() ? "" : path + ".") + std::string(row.key) + "`";
}

nlohmann::json schema_of(const Setting& row);

nlohmann::json object_schema(Section section, std::span<const std::string_view> extra = {}) {
    nlohmann::json properties = nlohmann::json::object();
    nlohmann::json required = nlohmann::json::array();
    for (const auto& row : kSettings) {
        if (!in_section(row, section)) continue;
        properties[std::string(row.key)] = schema_of(row);
        if (row.required) required.push_back(row.key);
    }
    for (auto key : extra)
        properties[std::string(key)] = {{"description", "read by the protocol faces (docs/configuration.md#station-kind-and-other-protocols)"}};
    nlohmann::json schema = {{"type", "object"}, {"properties", properties}, {"additionalProperties", false}};
    if (!required.empty()) schema["required"] = required;
    return schema;
}

nlohmann::json schema_of(const Setting& row) {
    nlohmann::json s;
    if (row.holds != S::None) {
        auto object = object_schema(row.holds);
        if (row.type == T::Array) s = {{"type", "array"}, {"items", object}};
        else if (info(row.holds).keyed) s = {{"type", "object"}, {"additionalProperties", object}};
        else s = object;
    } else {
        switch (row.type) {
            case T::String: s["type"] = "string"; break;
            case T::Integer: s["type"] = "integer"; break;
            case T::Number: s["type"] = "number"; break;
            case T::Boolean: s["type"] = "boolean"; break;
            case T::Array: s["type"] = "array"; break;
            case T::Object: s["type"] = "object"; break;
            case T::Choice: {
                s["type"] = "string";
                auto list = nlohmann::json::array();
                for (auto c : choices_of(row)) list.push_back(c);
                s["enum"] = list;
                break;
            }
            case T::None: break;
        }
        // A template's port may be an expression in i ("20000+i"): plant_config.cpp resolves it first.
        if (row.key == "tcp_port" || row.key == "udp_port" || (row.section == S::Port && row.key == "port"))
            s["type"] = nlohmann::json::array({"integer", "string"});
        if (row.has_range() && (row.type == T::Integer || row.type == T::Number) && row.max < kAnyUnsigned) {
            s["minimum"] = row.type == T::Integer ? nlohmann::json(static_cast<std::uint64_t>(row.min)) : nlohmann::json(row.min);
            s["maximum"] = row.type == T::Integer ? nlohmann::json(static_cast<std::uint64_t>(row.max)) : nlohmann::json(row.max);
        }
        if (row.step) s["multipleOf"] = row.step;
    }
    if (row.key == "labels") s.erase("type");   // a list, or the name of a CSV file
    s["description"] = row.help.empty() ? row.doc : row.help;
    return s;
}

}  // namespace

std::span<const Setting> all_settings() { return kSettings; }

const Setting& setting(Section section, std::string_view key) {
    for (const auto& row : kSettings)
        if (in_section(row, section) && row.key == key) return row;
    throw std::logic_error("settings table: no row for key '" + std::string(key) + "'");
}

const Setting* setting_by_flag(std::string_view flag) {
    for (const auto& row : kSettings)
        if (!row.flag.empty() && row.long_flag() == flag) return &row;
    return nullptr;
}

std::vector<std::string_view> section_keys(Section section) {
    std::vector<std::string_view> keys;
    for (const auto& row : kSettings)
        if (in_section(row, section)) keys.push_back(row.key);
    return keys;
}

std::string_view section_name(Section section) { return info(section).path; }

bool is_choice(const Setting& row, std::string_view value) {
    for (auto c : choices_of(row))
        if (c == value) return true;
    return false;
}

void check_keys(const JsonAt& object, Section section, std::span<const std::string_view> extra) {
    auto keys = section_keys(section);
    keys.insert(keys.end(), extra.begin(), extra.end());
    object.only_keys(std::span<const std::string_view>(keys));
}

std::uint64_t whole_setting(const JsonAt& object, Section section, std::string_view key) {
    const auto& row = setting(section, key);
    return object[key].whole(static_cast<std::uint64_t>(row.min), whole_max(row), row.fix);
}

double number_setting(const JsonAt& object, Section section, std::string_view key) {
    const auto& row = setting(section, key);
    return object[key].number(row.min, row.max, row.fix);
}

std::uint64_t bounded_setting(const JsonAt& object, Section section, std::string_view key) {
    const auto& row = setting(section, key);
    auto at = object[key];
    auto value = at.unsigned_int(whole_max(row));
    if (value < row.min || (row.step && value % row.step != 0)) at.fail(row.below_min, row.fix);
    return value;
}

std::string choice_setting(const JsonAt& object, Section section, std::string_view key) {
    const auto& row = setting(section, key);
    auto at = object[key];
    auto value = at.string();
    if (!is_choice(row, value)) at.fail("unknown " + std::string(row.noun) + " '" + value + "'", row.fix);
    return value;
}

void check_flag_value(const Setting& row, double value) {
    if (!row.has_range() || row.own_check) return;
    auto min = row.min / row.flag_scale, max = row.max / row.flag_scale;
    if (value >= min && value <= max) return;
    auto fix = row.flag_fix.empty() ? row.fix : row.flag_fix;
    // "--tcp-port 70000: not a port number; use 0-65535": a fix that names the problem itself.
    bool names_problem = fix.starts_with("not ") || fix.starts_with("must ");
    throw ConfigError("--" + std::string(row.long_flag()) + " " + number_text(value) + ": " +
                      (names_problem ? "" : "out of range; ") + std::string(fix));
}

std::vector<std::string_view> settings_markdown_tables() {
    std::vector<std::string_view> names;
    for (const auto& t : kTables) names.push_back(t.name);
    return names;
}

std::string settings_markdown(std::string_view table) {
    std::string out;
    if (table == "cli") {
        out = "| Option | Key | Default | Meaning |\n|---|---|---|---|\n";
        for (const auto& row : kSettings) {
            if (row.flag.empty()) continue;
            std::string d = row.default_text.empty() ? "—" : default_cell(row);
            if (row.flag == "no-http") d = "—";
            out += "| " + flag_cell(row) + " | " + key_path(row) + " | " + d + " | " + std::string(row.help) + " |\n";
        }
        return out;
    }
    out = "| Key | Type | Default | Meaning |\n|---|---|---|---|\n";
    for (const auto& row : kSettings) {
        if (row.key.empty() || table_of(row) != table) continue;
        auto meaning = std::string(row.doc.empty() ? row.help : row.doc);
        if (row.has_range() && !row.own_check && row.doc.empty() && row.doc_type.empty() && row.max < kAnyUnsigned &&
            (row.section == S::Program || row.section == S::TimerLimit || row.section == S::Timing))
            meaning += " (" + number_text(row.min) + "–" + number_text(row.max) + ")";
        auto key = key_text(row, table);
        out += "| " + key + " | " + type_text(row) + " | " + default_cell(row) + " | " + meaning + " |\n";
    }
    return out;
}

nlohmann::json settings_json_schema() {
    std::vector<std::string_view> extra{"kind"};   // and the faces' sections (frontends/registry.cpp)
    for (const auto* face : frontends::faces()) extra.push_back(face->name());
    auto station = object_schema(S::Station, extra);
    auto plant = station;
    for (const char* key : {"threads", "shards", "shard_host", "metrics_by"})
        plant["properties"][key] = schema_of(setting(S::Plant, key));
    auto stations = schema_of(setting(S::Plant, "stations"));
    // A station entry: its own keys, or a template of them ("template", "count", "first").
    auto entry = station;
    for (auto key : section_keys(S::Template)) entry["properties"][std::string(key)] = schema_of(setting(S::Template, key));
    stations["items"] = entry;
    plant["properties"]["stations"] = stations;
    plant["$schema"] = "https://json-schema.org/draft/2020-12/schema";
    plant["title"] = "slmp-sim configuration (generated from config/settings.cpp; docs/configuration.md)";
    return plant;
}

}  // namespace slmp::config
