// pccd: command-line front end of the PCCD library (point cloud collision detection).
#include "commands.h"

#include <PCCD/Error.h>
#include <PCCD/version.h>

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

int main(int argc, char** argv)
{
    CLI::App app{"pccd " PCCD_VERSION_STRING
                 " -- collision detection and intersection of point clouds without surface reconstruction"};
    app.require_subcommand(1);
    app.set_version_flag("--version", PCCD_VERSION_STRING);
    pccd_tool::register_info(app);
    pccd_tool::register_demo(app);
    pccd_tool::register_kinetic_bench(app);
    pccd_tool::register_eval(app);
    pccd_tool::register_collide(app);
    pccd_tool::register_distance(app);
    pccd_tool::register_clearance(app);
    pccd_tool::register_contact_time(app);
    pccd_tool::register_bench(app);
    pccd_tool::register_render(app);
    pccd_tool::register_prepare(app);
    pccd_tool::register_world(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const PCCD::Error& e) {
        std::cerr << "pccd: error: " << e.what() << '\n';
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "pccd: unexpected error: " << e.what() << '\n';
        return 2;
    }
    return 0;
}
