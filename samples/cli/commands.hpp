// The `snell` commands.
#pragma once

#include "cli_args.hpp"

namespace snell::cli {

/// `snell info`: devices and the one Context::create would choose. Returns the exit code.
int run_info();
/// `snell list`: every registered effect with its parameter schema.
int run_list();
/// `snell render`: renders, prints timings, writes the PNG. Returns the exit code.
int run_render(const RenderOptions& options);
/// `snell bench`: plain frames against frames with effects, medians and ratio, optional JSON.
int run_bench(const RenderOptions& options);
/// `snell view`: the interactive viewer. Defined by samples/viewer, built when
/// SNELL_BUILD_VIEWER is ON (then SNELL_HAVE_VIEWER is defined for main.cpp).
int run_view(const RenderOptions& options);

} // namespace snell::cli
