// roomscout command line: one binary, one subcommand per job.

#include <CLI/CLI.hpp>
#include <iostream>

#include "roomscout/exploration/strategy_registry.hpp"

int main(int argc, char** argv) {
  CLI::App app{"roomscout: semantic-region-aware exploration of indoor buildings"};
  app.require_subcommand(1);
  auto* methods = app.add_subcommand("methods", "List the exploration methods");
  methods->callback([] {
    for (const auto& e : roomscout::strategyRegistry()) std::cout << e.name << "\t" << e.description << "\n";
  });
  CLI11_PARSE(app, argc, argv);
  return 0;
}
