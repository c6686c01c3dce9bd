// `snell`: renders Snell's scenes and effects headlessly (see --help).
#include "cli_args.hpp"
#include "commands.hpp"

// Sanitizer builds only: lets LeakSanitizer attribute the Vulkan driver's own leaks.
#include "../../tests/sanitizers/pin_vulkan_libraries.hpp"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  auto cmd = snell::cli::parse(args);
  if (!cmd) {
    std::fprintf(stderr, "snell: %s\n", cmd.error().message.c_str());
    return 2;
  }
  try {
    if (cmd->name == "help") {
      std::fputs(snell::cli::help_text().c_str(), stdout);
      return 0;
    }
    if (cmd->name == "info") {
      return snell::cli::run_info();
    }
    if (cmd->name == "list") {
      return snell::cli::run_list();
    }
    if (cmd->name == "bench") {
      return snell::cli::run_bench(cmd->render);
    }
    if (cmd->name == "view") {
#if defined(SNELL_HAVE_VIEWER)
      return snell::cli::run_view(cmd->render);
#else
      std::fprintf(stderr, "snell: view: this snell was built without the viewer "
                           "(SNELL_BUILD_VIEWER=OFF: it needs GLFW and Dear ImGui, Debian "
                           "libglfw3-dev and libimgui-dev)\n");
      return 2;
#endif
    }
    return snell::cli::run_render(cmd->render);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "snell: internal error: %s\n", e.what());
    return 1;
  }
}
