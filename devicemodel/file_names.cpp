// Names and paths a client may use, DOS date/time, and what kind of file a
// name is (docs/files.md "Names and paths"). Nothing a client sends can name
// something outside its drive: "." and "..", empty names, separators other
// than "\" between names, drive letters (":"), control characters, the
// characters FAT forbids and the DOS device names are refused here, before
// any store sees the name.
#include <algorithm>
#include <array>
#include <cctype>
#include <ctime>

#include "devicemodel/drives.hpp"
#include "devicemodel/utf16.hpp"

namespace slmp::devicemodel {
namespace {

constexpr std::size_t kMaxLongName = 64, kMaxLongPath = 252;

std::string upper(std::string_view text) {
    std::string out(text);
    for (auto& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

std::string extension(const std::string& name) {
    auto dot = name.rfind('.');
    return dot == std::string::npos ? std::string() : upper(name.substr(dot + 1));
}

bool device_name(const std::string& name) {
    auto base = upper(name.substr(0, name.find('.')));
    static constexpr std::array<std::string_view, 4> kFixed{"CON", "PRN", "AUX", "NUL"};
    if (std::find(kFixed.begin(), kFixed.end(), base) != kFixed.end()) return true;
    return base.size() == 4 && (base.starts_with("COM") || base.starts_with("LPT")) && base[3] >= '0' && base[3] <= '9';
}

bool valid_name(const std::string& name, NameForm form) {
    if (name.empty() || name == "." || name == "..") return false;
    if (name.back() == '.' || name.back() == ' ') return false;
    for (unsigned char c : name) {
        if (c < 0x20 || c == 0x7F) return false;
        if (std::string_view("\\/:*?\"<>|").find(static_cast<char>(c)) != std::string_view::npos) return false;
    }
    if (device_name(name)) return false;
    if (form == NameForm::Short83) {
        // 8 + "." + 3 bytes (4 full-width characters in the base), one dot at most.
        auto dot = name.find('.');
        if (dot != name.rfind('.')) return false;
        auto base = dot == std::string::npos ? name.size() : dot;
        auto ext = dot == std::string::npos ? 0 : name.size() - dot - 1;
        return base >= 1 && base <= 8 && ext <= 3 && name.find(' ') == std::string::npos;
    }
    return utf8_to_utf16(name).size() <= kMaxLongName;
}

}  // namespace

std::optional<std::vector<std::string>> split_checked(const std::string& path, NameForm form, bool allow_root) {
    std::vector<std::string> names;
    if (form == NameForm::Short83) {
        if (path.empty()) return allow_root ? std::optional(names) : std::nullopt;
        if (!valid_name(path, form)) return std::nullopt;
        names.push_back(path);
        return names;
    }
    std::string_view rest(path);
    if (rest.starts_with('\\')) rest.remove_prefix(1);   // "a leading \ is also accepted" (§3.3)
    if (utf8_to_utf16(rest).size() > kMaxLongPath) return std::nullopt;
    if (rest.empty()) return allow_root ? std::optional(names) : std::nullopt;
    while (true) {
        auto cut = rest.find('\\');
        std::string name(rest.substr(0, cut));
        if (!valid_name(name, form)) return std::nullopt;
        names.push_back(std::move(name));
        if (cut == std::string_view::npos) break;
        rest.remove_prefix(cut + 1);
    }
    return names;
}

std::uint16_t dos_time(std::int64_t seconds) {
    std::time_t t = static_cast<std::time_t>(seconds);
    std::tm tm{};
    ::localtime_r(&t, &tm);
    return static_cast<std::uint16_t>(tm.tm_hour << 11 | tm.tm_min << 5 | tm.tm_sec / 2);
}

std::uint16_t dos_date(std::int64_t seconds) {
    std::time_t t = static_cast<std::time_t>(seconds);
    std::tm tm{};
    ::localtime_r(&t, &tm);
    int year = std::clamp(tm.tm_year + 1900 - 1980, 0, 127);   // FAT dates run 1980-2107
    return static_cast<std::uint16_t>(year << 9 | (tm.tm_mon + 1) << 5 | tm.tm_mday);
}

std::optional<std::int64_t> from_dos(std::uint16_t date, std::uint16_t time) {
    int year = (date >> 9) + 1980, month = (date >> 5) & 0x0F, day = date & 0x1F;
    int hour = time >> 11, minute = (time >> 5) & 0x3F, second = (time & 0x1F) * 2;
    if (month < 1 || month > 12 || day < 1 || day > 31 || hour > 23 || minute > 59 || second > 59) return std::nullopt;
    std::tm tm{};
    tm.tm_year = year - 1900;
    tm.tm_mon = month - 1;
    tm.tm_mday = day;
    tm.tm_hour = hour;
    tm.tm_min = minute;
    tm.tm_sec = second;
    tm.tm_isdst = -1;
    auto t = std::mktime(&tm);
    if (tm.tm_mday != day) return std::nullopt;   // 31 April and the like roll over
    return static_cast<std::int64_t>(t);
}

// Q/L file kinds by extension (docs/files.md): programs QPG (and PRG), the
// parameter file QPA, the boot file QBT (inferred); the project-data
// extensions of §4.2 that 1820 refuses.
bool DriveSet::program_file(const std::string& name) {
    auto ext = extension(name);
    return ext == "QPG" || ext == "PRG";
}
bool DriveSet::parameter_file(const std::string& name) {
    auto ext = extension(name);
    return ext == "QPA" || ext == "PRM";
}
bool DriveSet::boot_file(const std::string& name) { return extension(name) == "QBT"; }
bool DriveSet::project_data(const std::string& name) {
    static constexpr std::array<std::string_view, 8> kProject{"DAT", "PRG", "QPG", "PFB", "QCD", "DCM", "QDI", "DID"};
    auto ext = extension(name);
    return std::find(kProject.begin(), kProject.end(), ext) != kProject.end();
}

}  // namespace slmp::devicemodel
