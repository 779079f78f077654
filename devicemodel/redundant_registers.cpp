#include "devicemodel/redundant_registers.hpp"

#include "devicemodel/special_registers.hpp"

namespace slmp::devicemodel {

namespace {

// Where a family keeps each flag (0: it has none).
struct RedundantRow {
    std::uint32_t system_a, system_b, control, standby;   // SM
    std::uint32_t own_cause, switch_cause, failure;       // SD
};

constexpr RedundantRow kQnPRH{1511, 1512, 1515, 1516, 1588, 1601, 0};
constexpr RedundantRow kIQR{1632, 1633, 1634, 1635, 1643, 1649, 1644};   // SM numbers inferred (header)

}  // namespace

void publish_redundant(DeviceMemory& memory, Family family, const RedundantStatus& status) {
    if (family == Family::IQF) return;
    const auto& row = family == Family::IQR ? kIQR : kQnPRH;
    special::set_sm(memory, row.system_a, !status.system_b);
    special::set_sm(memory, row.system_b, status.system_b);
    special::set_sm(memory, row.control, status.control);
    special::set_sm(memory, row.standby, !status.control);
    special::set_sd(memory, row.own_cause, static_cast<std::uint16_t>(status.own_cause));
    special::set_sd(memory, row.switch_cause, static_cast<std::uint16_t>(status.switch_cause));
    if (row.failure) special::set_sd(memory, row.failure, static_cast<std::uint16_t>(status.failure));
}

}  // namespace slmp::devicemodel
