#include "rocksweep/app/stored_options.hpp"

#include <set>
#include <sstream>

#include "rocksweep/core/errors.hpp"
#include "rocksweep/io/hdf5.hpp"

namespace rocksweep {

std::map<std::string, std::string> config_values(const std::string& text) {
    std::map<std::string, std::string> values;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        const auto eq = line.find(" = ");
        if (line.empty() || line[0] == '[' || line[0] == '#' || eq == std::string::npos) continue;
        values[line.substr(0, eq)] = line.substr(eq + 3);
    }
    return values;
}

void check_same_options(const std::string& path, const std::string& config_text, const std::string& what) {
    std::string stored;
    try {
        stored = h5::read_string_attribute(h5::File::open_read_only(path).open_group("provenance"), "config");
    } catch (const Hdf5Error&) {
        throw InputError("output", path, "a file of a rocksweep " + what + " to resume (it is damaged or not one)");
    }
    const auto was = config_values(stored), now = config_values(config_text);
    std::set<std::string> keys;
    for (const auto& [key, value] : was) keys.insert(key);
    for (const auto& [key, value] : now) keys.insert(key);
    // How the work is cut up and saved never changes a bit of the results (as for sweep --resume).
    const std::set<std::string> free_to_change{"chunk", "checkpoint-interval", "lanes"};
    for (const std::string& key : keys) {
        const std::string option = key.substr(key.rfind('.') + 1);  // "design.refine" is --refine in [design]
        if (free_to_change.count(option)) continue;
        const auto w = was.find(key), n = now.find(key);
        const std::string before = w == was.end() ? "not given" : w->second, after = n == now.end() ? "(not given)" : n->second;
        if (before != after)
            throw InputError(option, after,
                             before + ", as " + path + " was computed with (--resume continues a " + what +
                                 " only with the options it was started with; --overwrite starts afresh)");
    }
}

}  // namespace rocksweep
