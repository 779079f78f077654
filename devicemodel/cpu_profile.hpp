// A CPU profile: what makes one MELSEC CPU differ from another as a CPU — its
// identity, family, device sizes, the special registers that publish them and
// its remote password rule — as plain data. What its SLMP port answers is
// protocol::PortProfile; both come from one file (config/profiles/*.json).
// Facts: real-CPU measurements.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "devicemodel/device_table.hpp"
#include "devicemodel/drive_spec.hpp"

namespace slmp::devicemodel {

enum class Family : std::uint8_t { IQR, QnU, L, QJ71E71, IQF };

// A special register that publishes one device's configured size (§6).
struct SizeRegister {
    Area area;
    std::uint16_t sd;      // SD number
    std::uint8_t bits;     // 16 or 32
};

using DeviceSizes = std::array<std::uint32_t, static_cast<std::size_t>(Area::Count)>;

struct CpuProfile {
    std::string name;                 // profile id, e.g. "R08CPU"
    std::string type_name;            // 0101 model name (≤ 16 characters)
    std::uint16_t model_code = 0;     // 0101 model code
    Family family = Family::IQR;
    Numbering numbering;              // X/Y in hex, or in octal on iQ-F (profile "xy_radix")

    DeviceSizes sizes{};
    std::vector<Area> start_only_range_check;   // iQ-R: R and ZR check the start only
    std::vector<SizeRegister> size_registers;
    // 0613/1613 reach a buffer memory of the port's own (e.g. a QJ71E71-100) of
    // this many words; 0 = the CPU buffer memory (area G of the CPU).
    std::uint32_t station_buffer_words = 0;

    // Remote password length rule (SLMP Reference Manual §5.7): Q/L exactly 4
    // characters, iQ-R 6-32. 0/0: the port has no remote password (1630/1631 -> C059).
    std::uint8_t password_min_length = 0;
    std::uint8_t password_max_length = 0;

    // The file drives (profile "file_drives", docs/files.md): none on a CPU
    // whose port does not serve the file commands.
    std::vector<DriveSpec> drives;

    std::uint32_t size(Area area) const { return sizes[static_cast<std::size_t>(area)]; }
};

}  // namespace slmp::devicemodel
