#include "tools/bench/process_cpu.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <charconv>
#include <fstream>
#include <string>

namespace slmp::bench {

std::optional<double> cpu_seconds_from_stat(std::string_view line, double ticks_per_second) {
    // The command name (field 2) is in parentheses and may itself hold spaces
    // and ')', so count fields from the last ')'.
    auto close = line.rfind(')');
    if (close == std::string_view::npos) return std::nullopt;
    std::string_view rest = line.substr(close + 1);
    unsigned long long utime = 0, stime = 0;
    int field = 2;   // the ')' ends field 2
    std::size_t i = 0;
    while (field < 15) {
        while (i < rest.size() && rest[i] == ' ') ++i;
        if (i == rest.size()) return std::nullopt;
        std::size_t end = rest.find(' ', i);
        if (end == std::string_view::npos) end = rest.size();
        ++field;
        if (field == 14 || field == 15) {
            auto& into = field == 14 ? utime : stime;
            auto [p, error] = std::from_chars(rest.data() + i, rest.data() + end, into);
            if (error != std::errc{} || p != rest.data() + end) return std::nullopt;
        }
        i = end;
    }
    return static_cast<double>(utime + stime) / ticks_per_second;
}

std::optional<double> process_cpu_seconds(pid_t pid) {
    std::ifstream file("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!file || !std::getline(file, line)) return std::nullopt;
    return cpu_seconds_from_stat(line, static_cast<double>(::sysconf(_SC_CLK_TCK)));
}

double own_cpu_seconds() {
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) / 1e6; };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

}  // namespace slmp::bench
