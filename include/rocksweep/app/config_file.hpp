#pragma once
/// Config files: a strict reader of the TOML our users write, in place of CLI11's own.
#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace rocksweep {

/// Reads comments, bare and quoted keys (dotted too), basic and literal strings, integers and
/// floats (underscores between digits), booleans, arrays (over several lines, trailing comma),
/// and tables. A table named after a subcommand (`[sweep]`) holds that subcommand's options,
/// as in CLI11; a table named after an option group (`[block]`) only groups top-level options.
/// `key = ""` leaves the option unset: that is how ConfigTOML writes an option without a value.
/// A byte-order mark opens the file at most; anything else the subset does not hold — a
/// repeated key, a control character or BOM in a key, an unknown table, an inline table, a
/// date — throws InputError("config", FILE, "line N: what"). effective_config() writes what
/// this reads back.
class TomlConfig : public CLI::ConfigTOML {
public:
    /// `file_name` says which file is being read, for messages.
    TomlConfig(std::vector<std::string> subcommands, std::vector<std::string> groups,
               std::function<std::string()> file_name);
    std::vector<CLI::ConfigItem> from_config(std::istream& input) const override;

private:
    std::vector<std::string> subcommands_, groups_;
    std::function<std::string()> file_name_;
};

/// The options of `app` after a parse, and of its subcommand `subcommand`, as text that
/// TomlConfig reads back to the same values: one `key = value` per line, the subcommand's
/// options as `subcommand.key`. An option is written when `written(name)` holds (name as in a
/// config) and it has a value: as given — the very strings CLI11 parsed, so that a replay is
/// bitwise the same — or else its default; numbers and booleans bare, other words quoted, an
/// option that takes several values as an array. A flag is written only when given, an option
/// without a value never (no `key = ""`).
std::string effective_config(const CLI::App& app, const std::string& subcommand,
                             const std::function<bool(const std::string& name)>& written);

}  // namespace rocksweep
