#pragma once
// POV-Ray's INI files, read the way POV-Ray reads them:
//
//   ; a comment (also // to the end of the line)
//   Width=640                      Key=value (keys are case-insensitive, spaces around = allowed)
//   Input_File_Name="walk.pov"     values may be quoted
//   +W640 +H480 -D                 raw switches, several to a line
//   Declare=Speed=2.5
//   [Fast]                         a section: read only when asked for, as walk.ini[Fast]
//   Antialias=off
//
// Without a section the file is read up to its first [section] line; `file.ini[Name]` reads
// that part and then the section Name (case-insensitive). A section that is not in the file
// is an error (POV-Ray silently reads nothing). Include_INI=other.ini reads another file at
// that point. This file only splits the text into entries; what the keys mean is
// render_options.cpp's business.
#include <string>
#include <vector>

#include "util/error.hpp"

namespace convray::app {

struct IniEntry {
  SourceLoc loc;        // of the key or switch
  SourceLoc value_loc;  // of the value (the key's location for a switch)
  std::string key;      // as written; empty for a switch
  std::string value;    // unquoted; the switch itself ("+W640") for a switch
  bool is_switch() const { return key.empty(); }
};

// Whether a command-line argument names an INI file: it ends with .ini (any case), possibly
// followed by a [section].
bool is_ini_argument(const std::string& argument);

// "walk.ini[Fast]" -> {"walk.ini", "Fast"}; no brackets: an empty section.
struct IniArgument {
  std::string path;
  std::string section;
};
IniArgument split_ini_argument(const std::string& argument);

// The entries of one file, in order, Include_INI expanded in place (at most 16 deep).
// Throws InputError ("file:line:col: what is wrong") for a file that cannot be read, a
// malformed line, a missing section, or an include cycle.
std::vector<IniEntry> read_ini(const IniArgument& argument);

}  // namespace convray::app
