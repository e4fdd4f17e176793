#pragma once
/// `rocksweep basin`: the basins of attraction of every scenario of a config (paper Fig. 7),
/// simulated on a grid of initial states and predicted by energy.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "rocksweep/app/options.hpp"

namespace rocksweep {

struct BasinCommand {
    std::string output;
    bool overwrite = false, quiet = false;
    std::vector<double> theta_range{-1.5, 1.5};       ///< theta / alpha
    std::vector<double> theta_dot_range{-0.45, 0.45};  ///< theta_dot / p
    std::size_t theta_points = 201, theta_dot_points = 201;
};

/// Adds `basin` and its own options to `app`; the model options are the app's (fallthrough).
CLI::App* add_basin_command(CLI::App& app, BasinCommand& cmd);

/// Refuses, naming it, an option typed on the command line that basin would ignore: the pulse
/// and the spectra grid (`args`: the command line without the program name).
void check_basin_options(const CLI::App& app, const std::vector<std::string>& args);

/// Computes and writes the maps (call it on one rank). Returns the exit status; throws
/// InputError for bad input before anything is written.
int run_basin(const Options& o, const BasinCommand& cmd, const std::string& config_text);

}  // namespace rocksweep
