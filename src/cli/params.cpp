// `moa params`: the parameter table as the library reports it (moa_param_count/_info_get), so
// the list can never drift from what moa_set_param accepts.
#include <cstdio>
#include <string>

#include "cli/cli.hpp"
#include "moa/moa.h"

namespace moa::cli {

const char *const kParamsHelp =
    "Usage: moa params [--markdown]\n"
    "\n"
    "Lists every reconstruction parameter with its default, its range and what it does.\n"
    "  --markdown   print the list as the Markdown table of the README\n"
    "Set one with: moa reconstruct INPUT -o OUTPUT --param NAME=VALUE\n";

namespace {

// Prints text wrapped at `width` columns, each line indented by `indent` spaces.
void print_wrapped(const std::string &text, size_t indent, size_t width) {
  size_t column = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find(' ', pos);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(pos, end - pos);
    if (column > 0 && column + 1 + word.size() > width) {
      std::printf("\n");
      column = 0;
    }
    if (column == 0) {
      std::printf("%*s%s", int(indent), "", word.c_str());
      column = indent + word.size();
    } else {
      std::printf(" %s", word.c_str());
      column += 1 + word.size();
    }
    pos = end + 1;
  }
  std::printf("\n");
}

}  // namespace

int run_params(int argc, char **argv) {
  ArgWalker args(argc, argv, "params");
  bool markdown = false;
  while (args.next()) {
    if (args.is("-h", "--help")) {
      std::fputs(kParamsHelp, stdout);
      return kExitOk;
    }
    if (args.is(nullptr, "--markdown")) {
      markdown = true;
      continue;
    }
    args.unknown();
  }
  const size_t count = moa_param_count();
  if (markdown) {
    std::printf("| name | default | range | description |\n|---|---|---|---|\n");
    for (size_t i = 0; i < count; ++i) {
      moa_param_info info;
      if (moa_param_info_get(i, &info) != MOA_OK)
        throw CliError(kExitInternal, "cannot read parameter " + std::to_string(i));
      std::string description = info.description;
      for (std::size_t at = 0; (at = description.find('|', at)) != std::string::npos; at += 2)
        description.replace(at, 1, "\\|");  // a bare | would end the table cell
      std::printf("| `%s` | %g | %g to %g%s | %s |\n", info.name, info.default_value,
                  info.min_value, info.max_value, info.is_integral ? ", whole" : "",
                  description.c_str());
    }
    return kExitOk;
  }
  std::printf("%zu parameters (set with --param NAME=VALUE):\n", count);
  for (size_t i = 0; i < count; ++i) {
    moa_param_info info;
    if (moa_param_info_get(i, &info) != MOA_OK)
      throw CliError(kExitInternal, "cannot read parameter " + std::to_string(i) + ": " +
                                        moa_last_error(nullptr));
    std::printf("\n  %s = %g  (%s, %g to %g)\n", info.name, info.default_value,
                info.is_integral ? "integer" : "real", info.min_value, info.max_value);
    print_wrapped(info.description, 6, 78);
  }
  return kExitOk;
}

}  // namespace moa::cli
