// The settings table: every setting of a station, a plant and the command line
// is one row — its JSON key, its command-line flag, type, range, default and a
// line of help. The JSON loaders' unknown-key checks and range checks, the
// command-line parser and --help (server/options.cpp), docs/configuration.md's
// option tables and config/schema.json are built from or checked against it
// (tests/unit/test_settings_table.cpp). Model: Redis's standardConfig table.
//
// Not here: the station's "kind" and the other protocol faces' sections and
// flags — they belong to the faces (frontends/face.hpp, read by
// config/frontend_config.cpp), and the station's key check names them as extras.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace slmp::config {

class JsonAt;

// The JSON object a key sits in ("ports": [ {…} ] is Port, "cpu": {"program": {…}} is Program).
// A nested object is a section too, and the row that holds it names it
// (Setting::holds): "limits" holds ProfileLimits, whose "batch_words" holds
// PointLimit. section_name() is its path: "limits", "networks[]".
enum class Section : std::uint8_t {
    None,          // no section: a row that holds no object
    CommandLine,   // a flag with no key in the file (--help, --config, --ready-file, ...)
    Plant,         // the top of a file that may list "stations"
    Template,      // a template entry of "stations": "template", "count", "first" (beside the station's keys)
    Station,       // one station's top-level keys (and a plant's defaults)
    Port,          // an entry of "ports"
    Module,        // an entry of "modules"
    Network,       // an entry of "networks"
    MultiCpu,      // an entry of "cpus" (CPU No.2-4)
    Redundant,     // "redundant": one CPU of a redundant pair
    Multidrop,     // "multidrop": a station behind another's serial module
    Route,         // an entry of "routes": a routing parameter
    NodeSearch,    // "node_search": node search by broadcast
    Drive,         // a value of "drives" (keyed by drive number)
    Label,         // an entry of "labels"
    Structure,     // an entry of "structures"
    Member,        // an entry of a structure's "members"
    LabelsFile,    // a --labels JSON file
    Http,          // "http"
    Cpu,           // "cpu"
    Lockout,       // "cpu": {"password_lockout"}
    Timer,         // an entry of "cpu": {"timers"}
    Counter,       // an entry of "cpu": {"counters"}
    CpuError,      // "cpu": {"error"}
    Program,       // "cpu": {"program"}
    TimerLimit,    // "cpu": {"program": {"timer_limit"}}
    Timing,        // "timing"
    Profile,       // a CPU profile file (config/profiles/*.json)
    Frame1E,       // a profile's "frame_1e"
    Pipeline,      // a profile's "pipeline"
    EndCodes,      // a profile's "end_codes"
    Limits,        // a profile's "limits"
    PointLimit,    // a limit of "limits" that is one number: {"max", "end_code"}
    FormLimit,     // a limit of "limits" per request form: {"q", "iqr", "end_code"}
    ProfileTiming, // a profile's "timing": the Timing rows that say `also`
    Difference,    // a value of a profile's "manual_vs_hardware" (keyed by topic)
    FileDrive,     // a value of a profile's "file_drives" (keyed by drive number)
    DriveAlias,    // such a value that is another drive's second name: {"alias_of": 3}
    SizeRegister,  // an entry of a profile's "size_registers"
};

enum class SettingType : std::uint8_t { String, Integer, Number, Boolean, Choice, Array, Object, None };

// What the flag's value is on the command line (Boost.Program_options' value type).
enum class FlagArg : std::uint8_t {
    None,           // a switch: --no-http, --help
    Text,           // std::string
    Unsigned,       // unsigned
    Size,           // std::size_t
    Real,           // double
    UnsignedList,   // std::vector<unsigned>, multitoken: --tcp-port 5000 5001
    TextList,       // std::vector<std::string>, repeatable: --scenario a.json --scenario b.json
};

// A Setting's max that stands for "any 64-bit unsigned number" (timing.seed).
inline constexpr double kAnyUnsigned = 18446744073709551615.0;

struct Setting {
    Section section;
    std::string_view key;            // the JSON key in `section`; empty: command line only
    std::string_view flag;           // "profile,p" as Program_options takes it; empty: file only
    SettingType type;
    FlagArg flag_arg = FlagArg::None;
    double min = 0, max = 0;         // Integer/Number: the accepted range (for the key's unit)
    std::string_view choices = {};   // Choice: "binary|ascii|auto"
    std::string_view default_text = {};   // as the docs show it; empty: none
    std::string_view help = {};      // one line: --help, and the docs when `doc` is empty
    std::string_view fix = {};       // the hint of a key's range error: "use 1 to 1000 (default 10)"
    std::string_view doc = {};       // the docs' "Meaning" when it says more than `help`
    std::string_view doc_type = {};  // the docs' "Type" when the type's name says too little
    std::string_view doc_table = {}; // the docs table it is listed in, when not its section's
    double flag_scale = 1;           // the key's value = the flag's value × this (--idle-timeout s, idle_timeout_ms)
    std::string_view flag_fix = {};  // the hint of the flag's range error (default `fix`)
    bool required = false;           // the key must be given (in its object)
    bool own_check = false;          // range and form checked by its reader (numbers that go in pairs, steps)
    Section holds = Section::None;   // Object/Array: the section of its object, or of each entry
    Section also = Section::None;    // a key of this section too (the profile's "timing" takes Timing's model keys)
    // A whole number read with bounded_setting(): above `max` "value N is larger
    // than MAX; use a smaller number", below `min` this problem and `fix`.
    std::string_view below_min = {};
    bool plain_range = false;        // read by bounded_setting() (the messages above), not whole_setting()
    std::uint32_t step = 0;          // the value must be a multiple of this (wdt_ms: 10)
    std::string_view noun = {};      // Choice: what choice_setting()'s "unknown NOUN 'x'" calls a wrong value

    bool has_range() const { return min != 0 || max != 0; }
    // "profile" of "profile,p".
    std::string_view long_flag() const { return flag.substr(0, flag.find(',')); }
};

// Every row, in the order --help lists the flags and the docs list the keys.
std::span<const Setting> all_settings();
// The row of a key in a section; throws std::logic_error when there is none (a programming error).
const Setting& setting(Section section, std::string_view key);
// The row of a long flag ("tcp-port"), or null.
const Setting* setting_by_flag(std::string_view flag);
// The keys of a section, in table order.
std::vector<std::string_view> section_keys(Section section);
// The JSON pointer style name of a section: "" (Station), "ports[]", "http", "cpu", "cpu.program", ...
std::string_view section_name(Section section);

// The object must hold only its section's keys (and `extra`, keys read by
// another part: the faces'); an unknown key fails naming itself and the list.
void check_keys(const JsonAt& object, Section section, std::span<const std::string_view> extra = {});
// Whether `value` is one of a Choice row's choices ("info" of log_level).
bool is_choice(const Setting& row, std::string_view value);
// A key's value checked against its row: a whole number (Integer) or a number
// (Number) within the row's range, with the row's fix in the error.
std::uint64_t whole_setting(const JsonAt& object, Section section, std::string_view key);
double number_setting(const JsonAt& object, Section section, std::string_view key);
// A whole number no larger than the row's max (JsonAt::unsigned_int's message),
// then at least its min (the row's below_min; fix).
std::uint64_t bounded_setting(const JsonAt& object, Section section, std::string_view key);
// A Choice row's value: a string among its choices, else "unknown NOUN 'x'; fix".
std::string choice_setting(const JsonAt& object, Section section, std::string_view key);

// A flag's value against its row's range (in the flag's unit); throws
// ConfigError "--flag value: out of range; fix".
void check_flag_value(const Setting& row, double value);

// The generated docs: a Markdown table ("cli", "station", "port", "hardware",
// "http", "cpu", "program", "timing", "profile") and the JSON Schema of a
// configuration file.
std::string settings_markdown(std::string_view table);
std::vector<std::string_view> settings_markdown_tables();
nlohmann::json settings_json_schema();

}  // namespace slmp::config
