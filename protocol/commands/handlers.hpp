// Every command handler, one family per file in this folder.
#pragma once

#include "protocol/command_table.hpp"

namespace slmp::protocol::commands {

// device_batch.cpp — Read 0401 / Write 1401, subcommands 0000 0001 0002 0003.
EndCode batch_read(CommandContext& ctx);
EndCode batch_write(CommandContext& ctx);

// cpu_model.cpp — Read Type Name 0101.
EndCode read_type_name(CommandContext& ctx);

// loopback.cpp — Self Test 0619.
EndCode self_test(CommandContext& ctx);

}  // namespace slmp::protocol::commands
