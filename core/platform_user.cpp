// The user's environment (core/platform.h): environment variables as paths, the folders settings and
// screenshots go to, local time, and whether a stream is a terminal; split from core/platform.cpp (files
// and folders). Named platform*.cpp: its POSIX header is allowed here (scripts/check-windows).
#include "core/platform.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>

#if defined(_WIN32)
#include <io.h>  // _isatty, _fileno
#else
#include <unistd.h>  // isatty
#endif

namespace shadowlab::platform {

namespace fs = std::filesystem;

fs::path env_path(const char* name) {
#if defined(_WIN32)
  const std::wstring wide(name, name + std::strlen(name));  // our variable names are ASCII
  const wchar_t* value = _wgetenv(wide.c_str());
  return value && *value ? fs::path(value) : fs::path();
#else
  const char* value = std::getenv(name);
  return value && *value ? fs::path(value) : fs::path();
#endif
}

fs::path user_config_folder() {
#if defined(_WIN32)
  const fs::path appdata = env_path("APPDATA");  // the roaming profile: C:\Users\NAME\AppData\Roaming
  return appdata.empty() ? fs::path() : appdata / "shadowlab";
#elif defined(__APPLE__)
  const fs::path home = env_path("HOME");
  return home.empty() ? fs::path() : home / "Library" / "Application Support" / "shadowlab";
#else
  if (const fs::path xdg = env_path("XDG_CONFIG_HOME"); !xdg.empty()) return xdg / "shadowlab";
  const fs::path home = env_path("HOME");
  return home.empty() ? fs::path() : home / ".config" / "shadowlab";
#endif
}

fs::path user_pictures_folder() {
#if defined(_WIN32)
  const fs::path profile = env_path("USERPROFILE");  // C:\Users\NAME
  return profile.empty() ? fs::path() : profile / "Pictures";
#elif defined(__APPLE__)
  const fs::path home = env_path("HOME");
  return home.empty() ? fs::path() : home / "Pictures";
#else
  if (const fs::path xdg = env_path("XDG_PICTURES_DIR"); !xdg.empty()) return xdg;
  const fs::path home = env_path("HOME");
  if (home.empty()) return {};
  // xdg-user-dirs writes lines such as XDG_PICTURES_DIR="$HOME/Bilder" (a path under $HOME, or absolute).
  const fs::path config = env_path("XDG_CONFIG_HOME").empty() ? home / ".config" : env_path("XDG_CONFIG_HOME");
  constexpr std::uint64_t kMaxUserDirsBytes = 64 * 1024;  // a few hundred bytes; anything larger is not it
  try {
    std::istringstream lines(read_regular_file(config / "user-dirs.dirs", kMaxUserDirsBytes));
    const std::string key = "XDG_PICTURES_DIR=\"";
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind(key, 0) != 0 || line.size() < key.size() + 1 || line.back() != '"') continue;
      const std::string value = line.substr(key.size(), line.size() - key.size() - 1);
      if (value.rfind("$HOME/", 0) == 0 && value.size() > 6) return home / value.substr(6);
      if (!value.empty() && value[0] == '/') return fs::path(value);
    }
  } catch (const FileError&) {
    // No such file (no xdg-user-dirs): the default below.
  }
  return home / "Pictures";
#endif
}

std::tm local_time(std::time_t t) {
  std::tm out{};
#if defined(_WIN32)
  localtime_s(&out, &t);
#else
  localtime_r(&t, &out);
#endif
  return out;
}

bool is_terminal(std::FILE* stream) {
#if defined(_WIN32)
  return _isatty(_fileno(stream)) != 0;
#else
  return ::isatty(::fileno(stream)) != 0;
#endif
}

}  // namespace shadowlab::platform
