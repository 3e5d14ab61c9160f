#include "util/partial_files.hpp"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <random>

namespace convray {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kTag = ".convray.";

std::string host_name() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0 || name[0] == '\0') return "localhost";
  std::string host(name);
  for (char& c : host) {
    if (c == '/' || c == '\0') c = '_';
  }
  return host;
}

std::string random_word() {
  static std::mutex mutex;
  static std::random_device device;  // the kernel's entropy (getrandom)
  std::lock_guard lock(mutex);
  char text[16];
  std::snprintf(text, sizeof text, "%08x", unsigned(device()));
  return text;
}

// "HOST.PID.RANDOM" of a temporary's name, or false when `entry` is not one for `stem_name`.
bool owner_of(const std::string& stem_name, const std::string& entry, std::string& host,
              long& pid) {
  const std::string prefix = "." + stem_name + std::string(kTag);
  if (entry.compare(0, prefix.size(), prefix) != 0) return false;
  std::string_view rest(entry);
  rest.remove_prefix(prefix.size());
  if (rest.ends_with(".partial.d")) {
    rest.remove_suffix(std::string_view(".partial.d").size());
  } else if (rest.ends_with(".partial")) {
    rest.remove_suffix(std::string_view(".partial").size());
  } else {
    return false;
  }
  const size_t random_dot = rest.rfind('.');
  if (random_dot == std::string_view::npos || random_dot == 0) return false;
  const size_t pid_dot = rest.rfind('.', random_dot - 1);
  if (pid_dot == std::string_view::npos) return false;
  const std::string_view pid_text = rest.substr(pid_dot + 1, random_dot - pid_dot - 1);
  const auto [end, error] = std::from_chars(pid_text.data(), pid_text.data() + pid_text.size(), pid);
  if (error != std::errc() || end != pid_text.data() + pid_text.size() || pid <= 0) return false;
  host = std::string(rest.substr(0, pid_dot));
  return true;
}

// --- what a terminating signal removes -----------------------------------------------------

constexpr size_t kSlots = 64;
constexpr size_t kPathBytes = 4096;
struct Slot {
  std::atomic<int> state{0};  // 0 free, 1 being filled, 2 registered
  char path[kPathBytes];
};
std::array<Slot, kSlots> g_slots;
constexpr std::array<int, 4> kSignals = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

void remove_partials_and_die(int signal_number) {
  // Files first, then the private folders they were in (unlink and rmdir are
  // async-signal-safe; a folder that is not yet empty stays for the next run).
  for (Slot& slot : g_slots) {
    if (slot.state.load() == 2) ::unlink(slot.path);
  }
  for (Slot& slot : g_slots) {
    if (slot.state.load() == 2) ::rmdir(slot.path);
  }
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

void install_handlers_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int s : kSignals) {
      struct sigaction current {};
      if (::sigaction(s, nullptr, &current) != 0) continue;
      // A handler someone else installed (or an ignored signal) is left as it is.
      if (current.sa_handler != SIG_DFL || (current.sa_flags & SA_SIGINFO)) continue;
      struct sigaction ours {};
      ours.sa_handler = remove_partials_and_die;
      sigemptyset(&ours.sa_mask);
      ::sigaction(s, &ours, nullptr);
    }
  });
}

}  // namespace

fs::path partial_name_for(const fs::path& destination, const char* suffix) {
  std::string name(1, '.');
  name.append(destination.filename().string()).append(kTag).append(host_name());
  name.append(".").append(std::to_string(::getpid())).append(".").append(random_word());
  name.append(suffix);
  return destination.parent_path() / name;
}

bool is_orphaned_partial(const fs::path& destination, const std::string& entry) {
  std::string host;
  long pid = 0;
  if (!owner_of(destination.filename().string(), entry, host, pid)) return false;
  if (host != host_name()) return false;
  if (pid == long(::getpid())) return false;
  return ::kill(pid_t(pid), 0) != 0 && errno == ESRCH;
}

void remove_orphaned_partials(const fs::path& destination) {
  std::error_code error;
  const fs::path folder = destination.parent_path().empty() ? fs::path(".")
                                                            : destination.parent_path();
  fs::directory_iterator entries(folder, error);
  if (error) return;
  const uid_t user = ::getuid();
  for (const fs::directory_entry& entry : entries) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || name[0] != '.' || !is_orphaned_partial(destination, name)) continue;
    struct stat info {};
    if (::lstat(entry.path().c_str(), &info) != 0 || info.st_uid != user) continue;
    if (S_ISREG(info.st_mode)) {
      fs::remove(entry.path(), error);
    } else if (S_ISDIR(info.st_mode)) {
      fs::remove_all(entry.path(), error);  // does not follow links inside
    }
  }
}

void register_partial(const fs::path& path) {
  install_handlers_once();
  const std::string& text = path.native();
  if (text.size() >= kPathBytes) return;
  for (Slot& slot : g_slots) {
    int free = 0;
    if (!slot.state.compare_exchange_strong(free, 1)) continue;
    std::memcpy(slot.path, text.c_str(), text.size() + 1);
    slot.state.store(2);
    return;
  }
}

void unregister_partial(const fs::path& path) {
  for (Slot& slot : g_slots) {
    if (slot.state.load() == 2 && path.native() == slot.path) {
      slot.state.store(0);
      return;
    }
  }
}

}  // namespace convray
