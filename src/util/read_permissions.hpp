#pragma once
// The folders a scene may read files from, after POV-Ray's I/O restrictions: a scene names
// includes and meshes, and a scene from someone else must not be able to read
// `../../../etc/passwd` (nor print its first line in a syntax error).
//
// A path is allowed when, with every symbolic link resolved, it lies in one of the allowed
// folders or below. The command line allows the scene's folder, the working folder, the +L
// library paths, POV-Ray's include folder and the output folder, and widens the rule with
// --allow-read FOLDER or lifts it with --allow-read-anywhere (docs/language.md).
#include <string>
#include <vector>

namespace convray {

class ReadPermissions {
 public:
  // Allows `folder` and everything below it; a folder that does not exist allows nothing.
  void allow(const std::string& folder);
  // The same for a folder whose links are trusted (an installed, root-owned folder such as
  // POV-Ray's includes, whose fonts link into /usr/share/fonts): a path that lies in it by
  // its name is allowed wherever its links lead.
  void allow_with_links(const std::string& folder);
  void allow_anywhere() { anywhere_ = true; }

  bool anywhere() const { return anywhere_; }
  // Whether `path` (an existing file) may be read.
  bool allows(const std::string& path) const;
  // The allowed folders, as resolved, for messages.
  const std::vector<std::string>& folders() const { return folders_; }

 private:
  std::vector<std::string> folders_;  // canonical, without a trailing separator
  std::vector<std::string> trusted_;  // absolute and normalised, links not resolved
  bool anywhere_ = false;
};

}  // namespace convray
