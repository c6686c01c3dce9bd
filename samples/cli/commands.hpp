// The `snell` commands.
#pragma once

#include "cli_args.hpp"

namespace snell::cli {

/// `snell info`: devices and the one Context::create would choose. Returns the exit code.
int run_info();
/// `snell render`: renders, prints timings, writes the PNG. Returns the exit code.
int run_render(const RenderOptions& options);

} // namespace snell::cli
