// CLI::App declared for the headers whose functions take one: CLI11 is header-only and costly to
// compile, so only the sources that define a command line include it.
#pragma once

namespace CLI {
class App;
}  // namespace CLI
