#include "rocksweep/app/resume_check.hpp"

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <vector>

#include "rocksweep/core/errors.hpp"

namespace rocksweep {

namespace {

/// "sweep.pulse = \"ricker\"" -> pulse: ["\"ricker\""]; a list "[a, b]" gives its elements.
using Config = std::map<std::string, std::vector<std::string>>;

std::vector<std::string> elements(const std::string& value) {
    if (value.size() < 2 || value.front() != '[' || value.back() != ']') return {value};
    std::vector<std::string> out(1);
    bool quoted = false;
    for (std::size_t i = 1; i + 1 < value.size(); ++i) {
        const char c = value[i];
        if (c == '\\' && quoted && i + 2 < value.size()) {
            out.back() += c;
            out.back() += value[++i];
        } else if (c == '"') {
            quoted = !quoted;
            out.back() += c;
        } else if (c == ',' && !quoted) {
            out.emplace_back();
        } else if (!(c == ' ' && !quoted && out.back().empty())) {
            out.back() += c;
        }
    }
    return out;
}

Config parse(const std::string& text) {
    Config c;
    for (const auto& [table_key, value] : config_values(text)) {
        // A command's own options carry its table ("sweep.pulse"): a merged file resumed by
        // sweep compares its pulse with sweep's.
        const std::size_t dot = table_key.find('.');
        c[dot == std::string::npos ? table_key : table_key.substr(dot + 1)] = elements(value);
    }
    return c;
}

bool number(const std::string& s, double& x) {
    if (s.empty()) return false;
    char* end = nullptr;
    x = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && std::isfinite(x);
}

bool same(const std::vector<std::string>& a, const std::vector<std::string>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        double x, y;
        if (a[i] == b[i] || (number(a[i], x) && number(b[i], y) && x == y)) continue;
        return false;
    }
    return true;
}

/// As the user typed it: quotes off, a flag "given".
std::string shown(const std::vector<std::string>* v) {
    if (!v) return "not given";
    std::string out;
    for (std::string e : *v) {
        if (e.size() >= 2 && e.front() == '"' && e.back() == '"') e = e.substr(1, e.size() - 2);
        out += (out.empty() ? "" : " ") + e;
    }
    return out == "true" ? "given" : out;
}

}  // namespace

std::map<std::string, std::string> config_values(const std::string& text) {
    std::map<std::string, std::string> values;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        const std::size_t eq = line.find(" = ");
        if (line.empty() || line[0] == '[' || line[0] == '#' || eq == std::string::npos) continue;
        values[line.substr(0, eq)] = line.substr(eq + 3);
    }
    return values;
}

const std::set<std::string>& work_options() {
    static const std::set<std::string> work{"lanes", "chunk", "checkpoint-interval"};
    return work;
}

const std::set<std::string>& resumable_freely() {
    static const std::set<std::string> free = [] {
        std::set<std::string> s = work_options();
        s.insert({"part", "parts", "refine", "refine-axes", "axis", "scenario", "floor", "sa-period", "sa-damping"});
        return s;
    }();
    return free;
}

void check_resumed_config(const std::string& path, const std::string& stored, const std::string& now,
                          const std::set<std::string>& free) {
    if (stored.empty()) return;
    const Config before = parse(stored), after = parse(now);
    std::set<std::string> keys;
    for (const auto& [k, v] : before) keys.insert(k);
    for (const auto& [k, v] : after) keys.insert(k);
    for (const std::string& key : keys) {
        if (free.count(key)) continue;
        const auto b = before.find(key), a = after.find(key);
        const std::vector<std::string>* was = b == before.end() ? nullptr : &b->second;
        const std::vector<std::string>* is = a == after.end() ? nullptr : &a->second;
        if (was && is && same(*was, *is)) continue;
        throw InputError(key, shown(is),
                         shown(was) + ", as " + path +
                             " was computed with (--resume continues a file only with the settings that shaped its results)");
    }
}

}  // namespace rocksweep
