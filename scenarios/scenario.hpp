// A scenario as data: the plant's initial state, a timeline of values that
// move, triggers that react to devices and traffic, a rung program, faults on
// demand and an optional recorded session to answer from. Loaded from JSON by
// loader.hpp (schema: scenarios/schema.json; reference: docs/scenarios.md) and
// run by ScenarioRunner (runner.hpp). Plain structs, no behaviour.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "config/config.hpp"
#include "devicemodel/device_table.hpp"
#include "devicemodel/labels.hpp"
#include "devicemodel/operating_state.hpp"
#include "protocol/end_code.hpp"
#include "protocol/frame.hpp"
#include "scenarios/compare.hpp"
#include "scenarios/logic.hpp"

namespace slmp::scenarios {

inline constexpr double kForever = std::numeric_limits<double>::infinity();

// How a number lands in word devices: one word (signed or not), two words
// (low word first, as the CPU stores a 32-bit value), or an IEEE single in two
// words. Bit devices always take 0/1.
enum class ValueFormat : std::uint8_t { Int16, Int32, Float32 };

// A device, or a global label standing in for one (docs/scenarios.md, "Labels").
// The file names the label; bind_labels() resolves it against the CPU's label
// table when the scenario starts, since the loader does not know the CPU.
struct DeviceRef {
    devicemodel::DeviceAddress address;           // spec null for a label
    ValueFormat format = ValueFormat::Int16;      // a label's comes from its type
    std::string label = {};                       // the name as written; empty for a device
    std::optional<devicemodel::LabelRef> bound = {};   // set by bind_labels()
};

// "set": {"Tank1.Level": 50}: a number for a label (devices keep config's forms).
struct LabelValue {
    DeviceRef target;
    double value = 0;
};

// Devices [first, last] of one storage area, e.g. "D100-D199" (inclusive).
struct DeviceRange {
    devicemodel::Area area = devicemodel::Area::D;
    std::uint32_t first = 0;
    std::uint32_t last = 0;
};

// ---- initial state --------------------------------------------------------

struct InitialState {
    std::vector<config::InitialValue> devices;
    std::optional<devicemodel::RunSwitch> run_switch;
    std::optional<std::string> password;
    std::optional<devicemodel::CpuError> error;
};

// ---- timeline -------------------------------------------------------------

struct SetStep { std::vector<config::InitialValue> values; std::vector<LabelValue> labels; };
struct IncrementStep { DeviceRef device; double by = 1; };
struct RampStep { DeviceRef device; double from = 0, to = 0; };
struct SineStep { DeviceRef device; double center = 0, amplitude = 0, period_ms = 1000; };
struct SquareStep { DeviceRef device; double low = 0, high = 1, period_ms = 1000, duty = 0.5; };
struct RandomWalkStep { DeviceRef device; double start = 0, min = 0, max = 0, step = 1, every_ms = 100; };
struct CopyStep { devicemodel::DeviceAddress from, to; std::uint32_t points = 1; };
// Ondemand 2101 (docs/timing.md): the CPU sends these devices' words to the
// clients `to` names: "all", "tcp", "udp" or a TCP connection id ("3").
// A timeline step and a trigger action.
struct OndemandAction {
    devicemodel::DeviceAddress first;
    std::uint32_t points = 1;   // devices (bit devices: 16 to a word)
    std::string to = "all";
};

using StepAction = std::variant<SetStep, IncrementStep, RampStep, SineStep, SquareStep, RandomWalkStep, CopyStep,
                                OndemandAction>;

struct Step {
    StepAction action;
    double start_ms = 0;      // from the start of the timeline (or of the loop pass)
    double duration_ms = 0;   // 0: an instant; kForever: until the timeline ends
    std::string pointer;      // "/timeline/steps/3", for log lines
};

struct Timeline {
    std::vector<Step> steps;
    double duration_ms = 0;   // one pass; 0: until the last step ends
    std::uint64_t loops = 1;  // passes; 0 = forever
};

// ---- faults ---------------------------------------------------------------

using config::Transport;
enum class Access : std::uint8_t { Any, Read, Write };
// Which protocol a request came in: SLMP (the engine) or a protocol face on the
// same memory, by the face's name (frontends/face.hpp; static storage).
using Protocol = std::string_view;
inline constexpr Protocol kSlmp = "slmp";
std::string_view to_string(Protocol protocol);   // "slmp", or the face's name


struct FaultMatch {
    std::vector<std::uint16_t> commands;          // empty: any
    std::vector<std::uint16_t> subcommands;       // empty: any
    std::vector<DeviceRange> devices;             // any device of the request in any range
    Access access = Access::Any;                  // device reads or device writes only
    std::optional<protocol::FrameKind> frame;
    std::optional<protocol::Codec> code;
    std::optional<Transport> transport;
    std::optional<std::uint64_t> connection;      // the n-th connection since start (1 = first)
    std::optional<std::string> client;            // the client's IP address
    // The network No. and station No. the request's route names (docs/plants.md,
    // "Networks and routes"): a module's fault on the requests for one network.
    std::optional<std::uint8_t> route_network, route_station;
    // A fault matches one protocol's requests (SLMP unless "protocol" says
    // otherwise); a front end's commands by their text ("RD", "24").
    Protocol request_protocol = kSlmp;
    std::vector<std::string> frontend_commands;   // empty: any
};

enum class FaultKind : std::uint8_t {
    EndCode, Delay, NoResponse, Close, Reset, Split, Coalesce, Corrupt, RefuseConnections, PowerCycle,
};
enum class Corruption : std::uint8_t { Length, Subheader, Random };

struct FaultAction {
    FaultKind kind = FaultKind::NoResponse;
    protocol::EndCode end_code = protocol::EndCode::Ok;
    std::uint8_t frontend_code = 0;               // EndCode on a front end: host-link response code, JW RSLT
    double delay_min_ms = 0, delay_max_ms = 0;    // Delay: fixed when equal
    std::size_t chunks = 2;                       // Split: number of pieces...
    std::size_t chunk_bytes = 0;                  // ...or their size (wins when set)
    double pause_ms = 0;                          // Split: between pieces
    std::size_t responses = 2;                    // Coalesce: responses per write
    double hold_ms = 200;                         // Coalesce: longest wait for the rest
    Corruption corruption = Corruption::Random;
    std::size_t bytes = 1;                        // Corrupt random: bytes changed; Length: added to the field
    double period_ms = 0;                         // RefuseConnections: for; PowerCycle: power off
};

struct Fault {
    std::string id;
    std::string pointer;                          // "/faults/2"
    bool enabled = true;
    FaultMatch match;
    FaultAction action;
    std::uint64_t skip = 0;                       // let this many matching requests through first
    std::uint64_t count = 0;                      // fire at most this often; 0 = no limit
    double probability = 1;                       // seeded (Scenario::seed)
    double from_ms = 0, until_ms = kForever;      // window on the scenario clock
};

// ---- triggers -------------------------------------------------------------

// A side of a comparison: a device or a constant.
struct Operand {
    std::optional<DeviceRef> device;
    double constant = 0;
};

struct DeviceCondition {
    enum class Kind : std::uint8_t { Compare, Rising, Falling };
    Kind kind = Kind::Compare;
    Operand left;
    Compare op = Compare::Ne;
    Operand right;                                // "M0" alone means M0 != 0
};

struct TrafficCondition {
    std::vector<std::uint16_t> commands;
    std::vector<std::uint16_t> subcommands;
    std::vector<DeviceRange> devices;
    Access access = Access::Any;                  // "writes": [...] sets Write
    std::optional<std::string> client;
    std::uint64_t nth = 0;                        // only the n-th matching request; 0 = every one
};

struct TimeCondition { double at_ms = 0; };

using Condition = std::variant<DeviceCondition, TrafficCondition, TimeCondition>;

struct SetAction { std::vector<config::InitialValue> values; std::vector<LabelValue> labels; };
struct IncrementAction { DeviceRef device; double by = 1; };
struct PulseAction { devicemodel::DeviceAddress device; double ms = 100; };
struct SwitchAction { devicemodel::RunSwitch position = devicemodel::RunSwitch::Run; };
struct ErrorAction { devicemodel::CpuError error; };
struct ClearErrorAction {};
struct FaultSwitchAction { std::string fault; bool enable = true; };
struct PowerCycleAction { double off_ms = 1000; };
struct RefuseAction { double for_ms = 1000; };
struct LogAction { std::string text; };
// A redundant pair's system switch: the standby system becomes the control
// system (docs/plants.md, "Redundant pairs").
struct SystemSwitchAction {};
// {"drive": {"number": 2, "present": false}}: the SD card taken out (or put
// back), its LOCK switch moved (docs/files.md).
struct DriveAction {
    std::uint16_t number = 0;
    std::optional<bool> present;
    std::optional<bool> write_protect;
    std::string pointer;   // for the start-up check that the drive exists
};

using Action = std::variant<SetAction, IncrementAction, PulseAction, SwitchAction, ErrorAction, ClearErrorAction,
                            FaultSwitchAction, PowerCycleAction, RefuseAction, LogAction, OndemandAction, DriveAction,
                            SystemSwitchAction>;

// "D100-D109" (or one device "D100") and a target, as an Ondemand's data;
// nullopt with `error` set when the text names no device range.
std::optional<OndemandAction> parse_ondemand(std::string_view data, std::string to, std::string* error);

struct Trigger {
    std::string id;
    std::string pointer;                          // "/triggers/1"
    Condition when;
    double for_ms = 0;                            // device conditions: held this long
    std::uint64_t times = 0;                      // fire at most this often; 0 = no limit
    std::vector<Action> actions;
};

// ---- replay ---------------------------------------------------------------

struct ReplaySpec {
    std::string file;                             // JSON-lines recording (recording.hpp)
    enum class Miss : std::uint8_t { Simulate, EndCode, NoResponse };
    Miss on_miss = Miss::Simulate;                // a request the recording does not hold
    protocol::EndCode miss_code = protocol::EndCode::UnsupportedCommand;
};

// ---- the whole ------------------------------------------------------------

struct Scenario {
    std::string source;                           // the file, for messages
    std::string name;
    std::string description;
    // "stations": the plant's stations it is for (names or patterns such as
    // "press-*"); empty: every station it is given to.
    std::vector<std::string> stations;
    std::uint64_t seed = 1;
    InitialState initial;
    Timeline timeline;
    std::vector<Trigger> triggers;
    LogicProgram logic;
    std::vector<Fault> faults;
    std::optional<ReplaySpec> replay;
};

}  // namespace slmp::scenarios
