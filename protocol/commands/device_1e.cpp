// The A-compatible 1E frame's device commands (docs/frames.md): Batch Read
// 00/01, Batch Write 02/03 and Test bit units 04 decode here into the Operands
// the 3E decoders build for 0401/1401/1402, so the 3E handlers (check order
// and all: device_batch.cpp, device_random.cpp) serve them unchanged.
//   00-03  head device(6) points(1; 00 = 256) fixed 00(1) [write data]
//   04     points(1) fixed 00(1), per point: device(6) set/reset(1)
// Bit data come in whole bytes: an odd count carries one dummy point.
#include "protocol/commands/handlers.hpp"
#include "protocol/commands/limits.hpp"

namespace slmp::protocol::commands {

void decode_batch_1e(DecodeContext& d) {
    DeviceOperand device;
    device.field = read_device(d, "head device");
    unsigned points = d.in.u8("number of device points");
    auto fixed = d.in.u8("fixed value 00");
    if (!d.in.ok()) return fail_field(d);
    if (fixed != 0) fail(d, EndCode::LengthMismatch);
    device.points = points == 0 ? 256 : points;
    const bool bit_units = d.spec.access == Access::Bits;
    device.unit = bit_units ? DeviceOperand::Unit::Bit : DeviceOperand::Unit::Word;
    if (d.spec.writes()) {
        if (bit_units) {
            device.bits = d.in.bits(device.points + device.points % 2, "write data");
            device.bits.resize(device.points);   // the dummy point
        } else {
            device.words = d.in.words(device.points, "write data");
        }
    }
    d.out.devices.push_back(std::move(device));
    if (!d.in.finish()) fail_field(d, true);
}

void decode_test_bits_1e(DecodeContext& d) {
    auto points = d.in.u8("number of bit access points");
    auto fixed = d.in.u8("fixed value 00");
    if (!d.in.ok()) return fail_field(d);
    if (fixed != 0) fail(d, EndCode::LengthMismatch);
    if (over(d, d.port.random_write_bits, points)) fail(d, over_limit_code(d, d.port.random_write_bits));
    for (unsigned i = 0; i < points && d.in.ok(); ++i) {
        DeviceOperand device;
        device.field = read_device(d, "bit access device");
        device.unit = DeviceOperand::Unit::Bit;
        device.points = 1;
        device.bits = {static_cast<std::uint8_t>(d.in.u8("set/reset") != 0)};   // any nonzero value sets
        if (d.in.ok()) d.out.devices.push_back(std::move(device));
    }
    if (!d.in.finish()) fail_field(d);
}

}  // namespace slmp::protocol::commands
