// The command line's commands and options as data: each option says which commands take it, so
// that a command refuses the others by name and its --help lists only its own.
#pragma once

#include <string>
#include <vector>

namespace tsk::cli {

struct Options;

// The commands, one bit each, so that an option can name the commands that take it.
enum CommandBit : unsigned {
  kSilhouettes = 1u << 0,
  kProfiles = 1u << 1,
  kClassify = 1u << 2,
  kRowSlope = 1u << 3,
  kPStrokes = 1u << 4,
  kDrape = 1u << 5,
  kPanorama = 1u << 6,
  kFilterPlot = 1u << 7,
};

struct CommandSpec {
  const char* name;  // as typed: "row-slope"
  CommandBit bit;
  const char* summary;  // what it makes, for the usage
};

// Sets an option's value in `o`; `option` is its name, for messages. Throws Error on a bad value.
using OptionSetter = void (*)(Options& o, const std::string& option, const std::string& value);

struct OptionSpec {
  const char* name;     // "--azimuth"
  const char* value;    // what it takes ("DEG"), or nullptr for a flag
  const char* section;  // the heading it is listed under
  const char* help;     // one or more lines, without the name
  unsigned commands;    // the CommandBits of the commands that take it
  OptionSetter set;     // the value is empty for a flag
};

const std::vector<CommandSpec>& command_table();
const std::vector<OptionSpec>& option_table();

// The command of that name, or null.
const CommandSpec* find_command(const std::string& name);

// The program's usage: its commands, each with what it makes.
std::string program_usage();

// The help of one command: its usage, what it makes, and only the options it takes.
std::string command_help(const CommandSpec& command);

}  // namespace tsk::cli
