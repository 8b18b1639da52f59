// tools/commands.h -- the subcommands of the pccd tool. Each register_* function adds one CLI11
// subcommand to the app; its implementation lives in tools/command_<name>.cpp.
#pragma once

#include <CLI/CLI.hpp>

namespace pccd_tool {

void register_info(CLI::App& app);           // pccd info FILE [--json]
void register_demo(CLI::App& app);           // pccd demo
void register_kinetic_bench(CLI::App& app);  // pccd kinetic-bench --scene cloth|bunny|random --size N [--json]
void register_eval(CLI::App& app);           // pccd eval FILE --at "x y z" [--kernel K] [--json]
void register_collide(CLI::App& app);        // pccd collide A B [--transform-a ...] [--mode first|all] [--cases FILE]
void register_distance(CLI::App& app);       // pccd distance A B [--transform-a ...] [--penetration] [--margin M] [--cases FILE]
void register_clearance(CLI::App& app);      // pccd clearance OBJECT SCENE --path POSES.csv --margin M [--max-distance CAP] [--json] [--png F]
void register_contact_time(CLI::App& app);   // pccd contact-time A B [--from-a ...] [--to-a ...] [--motion linear|screw] [--cases FILE]
void register_render(CLI::App& app);         // pccd render A [B] [--transform-a ...] [--points P] [--out F.png]
void register_prepare(CLI::App& app);         // pccd prepare POINTS OUT [--kernel K] [--normalize] [--json]
void register_world(CLI::App& app);          // pccd world SCENE.csv | --generate FILE:COUNT [--json] [--png F.png]
void register_bench(CLI::App& app);          // pccd bench FILE [--method isearch|rst] [--distances a:b:s] [--csv OUT]

} // namespace pccd_tool
