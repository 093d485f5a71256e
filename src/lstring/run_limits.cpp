#include "lstring/run_limits.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstdio>

#include "lstring/module_string.h"

namespace sylva {
namespace {

thread_local RunBudget* active_budget = nullptr;

constexpr std::size_t kSmallestModuleBytes = abi::encoded_module_size(0, 0);  // a one-byte id alone
// String memory the default module limit allows each module: see default_run_limits.
constexpr std::size_t kMemoryPerModule = 64;

std::string bytes_text(std::size_t bytes) {
  static const char* const units[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  double value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 1024 && unit < 4) {
    value /= 1024;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", value, units[unit]);
  return text;
}

}  // namespace

RunLimits default_run_limits() {
  RunLimits limits;
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGESIZE);
  const std::size_t physical = pages > 0 && page_size > 0 ? static_cast<std::size_t>(pages) * static_cast<std::size_t>(page_size)
                                                          : std::size_t{8} << 30;
  limits.max_memory = physical / 2;
  limits.max_drawn_modules = max_modules_for_memory(limits.max_memory);
  return limits;
}

std::size_t max_modules_for_memory(std::size_t max_memory) { return max_memory / kMemoryPerModule; }

void RunBudget::start_clock() {
  deadline_ = limits_.timeout_seconds > 0
                  ? std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(limits_.timeout_seconds))
                  : std::chrono::steady_clock::time_point::max();
}

std::string RunBudget::where() const {
  const int step = step_.load(std::memory_order_relaxed);
  if (drawing_.load(std::memory_order_relaxed)) return "drawing after step " + std::to_string(step);
  return step == 0 ? "the axiom" : "step " + std::to_string(step);
}

void RunBudget::exceeded(const std::string& what, const std::string& option) const {
  throw LimitExceeded("sylva: error: " + where() + ": " + what + " (" + option + ")");
}

void RunBudget::check_time() const {
  if (std::chrono::steady_clock::now() > deadline_) {
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%g", limits_.timeout_seconds);
    exceeded(std::string("the run went past its time limit of ") + seconds + " s",
             "--timeout SECONDS sets another");
  }
}

bool RunBudget::more_modules_than(std::size_t max, const unsigned char* data, std::size_t bytes) const {
  if (max == 0 || sizes_ == nullptr || bytes / kSmallestModuleBytes <= max) return false;
  // Counted until the bytes left could not hold enough modules to cross the
  // limit: a string of modules larger than the smallest stops early (koch's
  // six-byte modules after a twelfth of the string), one of one-byte modules
  // is counted whole.
  std::size_t count = 0;
  for (std::size_t at = 0; at < bytes;) {
    at += sizes_[module_id_at(data, at)];
    if (++count > max) return true;
    if (at >= bytes || (bytes - at) / kSmallestModuleBytes <= max - count) return false;
  }
  return false;
}

void RunBudget::check_modules(const unsigned char* data, std::size_t bytes) const {
  if (more_modules_than(limits_.max_modules, data, bytes))
    exceeded("the string has more than " + std::to_string(limits_.max_modules) + " modules, the limit",
             "--max-modules N raises it");
}

void RunBudget::check_drawn_modules(const unsigned char* data, std::size_t bytes) const {
  if (more_modules_than(limits_.max_drawn_modules, data, bytes))
    exceeded("the string has more than " + std::to_string(limits_.max_drawn_modules) +
                 " modules, the most a drawing may have within the memory limit",
             "--max-memory SIZE raises it");
}

void RunBudget::check_memory(std::size_t more) const {
  if (limits_.max_memory == 0) return;
  const std::size_t total = string_bytes_in_use() + more;
  if (total > limits_.max_memory)
    exceeded("the strings would take " + bytes_text(total) + ", more than the limit of " +
                 bytes_text(limits_.max_memory),
             "--max-memory SIZE raises it");
}

std::size_t RunBudget::affordable(std::size_t wanted) const {
  if (limits_.max_memory == 0) return wanted;
  const std::size_t used = string_bytes_in_use();
  return used >= limits_.max_memory ? 0 : std::min(wanted, limits_.max_memory - used);
}

std::optional<std::size_t> parse_byte_size(const std::string& text) {
  std::size_t value = 0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end == text.data()) return std::nullopt;
  std::string unit(end, text.data() + text.size());
  for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (unit.size() > 1 && unit.back() == 'B') unit.pop_back();
  if (unit.size() > 1 && unit.back() == 'I') unit.pop_back();
  static const std::string units = "KMGT";
  int shift = 0;
  if (unit.size() == 1 && units.find(unit[0]) != std::string::npos)
    shift = 10 * (1 + static_cast<int>(units.find(unit[0])));
  else if (!unit.empty() && unit != "B")
    return std::nullopt;
  if (shift && value > (SIZE_MAX >> shift)) return std::nullopt;
  return value << shift;
}

RunBudget::Scope::Scope(RunBudget& budget) : outer_(active_budget) { active_budget = &budget; }
RunBudget::Scope::~Scope() { active_budget = outer_; }
RunBudget* RunBudget::active() { return active_budget; }

}  // namespace sylva
