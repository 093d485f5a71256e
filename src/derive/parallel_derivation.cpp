// Derivation passes on several threads, where the result cannot differ from
// a serial pass's: the old string is cut into chunks at module boundaries,
// each chunk is rewritten on its own (reading the whole old string for
// context) and the successors are joined in order. A pass is serial when
// one of its bodies may act beyond its successor (the translator's analysis,
// abi::ModelDescriptor::rule_parallel), reads the string being built (new
// context, backward steps), draws from one random sequence (ran() outside
// the keyed mode, cpfg's stochastic productions), or keeps state from
// module to module (cpfg's sub-L-systems, Gillespie steps, birth tracking).
#include <algorithm>
#include <cstring>
#include <exception>
#include <mutex>

#include "derive/derivation.h"
#include "derive/keyed_random.h"
#include "derive/worker_threads.h"
#include "lstring/run_limits.h"

namespace sylva::derive {
namespace {

// Chunks per thread: rewriting some parts of a string costs more than others.
constexpr std::size_t kChunksPerThread = 4;

// Where the cut before chunk `c` of `chunks` falls, as a fraction of the
// bytes. The chunks shrink from first to last, from 1.8 to 0.2 times the
// mean, as threads take them in order: a pass ends when its last chunk does,
// and a small last chunk leaves the other threads idle for less time. On two
// threads this took the derivation alone from 180 to 166 ms (koch) and from
// 148 to 138 ms (the branching model with context), median of 15 rounds.
double cut_fraction(std::size_t c, std::size_t chunks) {
  constexpr double kShrinking = 0.8;  // 0: chunks of equal size
  const double x = static_cast<double>(c) / static_cast<double>(chunks);
  return (1 - kShrinking) * x + kShrinking * x * (2 - x);
}

const char* kind_name(abi::RuleKind kind) {
  return kind == abi::RuleKind::Production ? "production" : "decomposition rule";
}

}  // namespace

std::string Derivation::serial_reason(abi::RuleKind kind) const {
  if (sub_lsystems_) return "the model has sub-L-systems, whose stack is followed module by module";
  if (kind == abi::RuleKind::Production && model_.before_module)
    return "the model's stochastic productions draw for every module in turn";
  if (kind == abi::RuleKind::Production && model_.gillespie_group_count > 0)
    return "the model has Gillespie groups";
  for (std::uint32_t r = 0; r < model_.rule_count; ++r) {
    const abi::Rule& rule = model_.rules[r];
    if (rule.kind != kind) continue;
    const std::string at = std::string(rule.file ? rule.file : "?") + ":" + std::to_string(rule.line) + ": " +
                           kind_name(kind) + " ";
    if (rule.part_length[abi::kNewLeft] > 0 || rule.part_length[abi::kNewRight] > 0)
      return at + "reads the new string as context";
    const std::uint8_t verdict = model_.rule_parallel ? model_.rule_parallel[r] : std::uint8_t{abi::kRuleSerial};
    if (verdict == abi::kRuleParallelIfKeyed && !keyed_random_)
      return at + "calls ran() (--random keyed lets it run in parallel)";
    if (verdict == abi::kRuleSerial) {
      const char* why = model_.rule_serial_reasons ? model_.rule_serial_reasons[r] : nullptr;
      return at + (why ? why : "was not analysed");
    }
  }
  return "";
}

std::string Derivation::parallel_explanation() const {
  if (threads_ < 2) return "derivation: serial (one thread)\n";
  std::string text;
  for (abi::RuleKind kind : {abi::RuleKind::Production, abi::RuleKind::Decomposition}) {
    if (!rules_.has_rules(kind)) continue;
    const std::string why = serial_reason(kind);
    text += std::string(kind == abi::RuleKind::Production ? "productions" : "decomposition") + ": " +
            (why.empty() ? "parallel on " + std::to_string(threads_) + " threads for strings of " +
                               std::to_string(2 * min_chunk_bytes_ >> 10) + " KiB or more" +
                               (kind == abi::RuleKind::Production ? " (forward steps, " : " (") + "births not tracked)"
                         : "serial: " + why) +
            "\n";
  }
  return text.empty() ? "derivation: no productions or decomposition rules\n" : text;
}

void Derivation::set_threads(int threads, std::size_t min_chunk_bytes) {
  threads_ = std::max(threads, 1);
  min_chunk_bytes_ = std::max<std::size_t>(min_chunk_bytes, 1);
  forward_parallel_ = serial_reason(abi::RuleKind::Production).empty();
  decomposition_parallel_ = serial_reason(abi::RuleKind::Decomposition).empty();
}

void Derivation::set_keyed_random(bool on) {
  keyed_random_ = on;
  set_threads(threads_, min_chunk_bytes_);
}

double Derivation::keyed_draw(void* host) {
  return keyed_random::draw(static_cast<Derivation*>(host)->keyed_seed_);
}

Derivation::KeyedRandomPass::KeyedRandomPass(Derivation& d, abi::RuleKind kind) : control(d.control()) {
  if (!d.keyed_random_) return;
  // The pass's seed: what the control statements left in ran()'s generator
  // (bodies do not advance it in this mode), the step and the kind of pass.
  d.keyed_seed_ = keyed_random::mix(keyed_random::mix(control.rand48, static_cast<std::uint64_t>(control.step)),
                                    static_cast<std::uint64_t>(kind));
  keyed_random::key = {};
  control.keyed_random = &Derivation::keyed_draw;
}

Derivation::KeyedRandomPass::~KeyedRandomPass() { control.keyed_random = nullptr; }

std::vector<std::size_t> Derivation::chunk_starts(const StringView& src) const {
  const std::size_t bytes = src.end - src.begin;
  if (threads_ < 2 || bytes < 2 * min_chunk_bytes_) return {};
  const std::size_t chunks =
      std::min(bytes / min_chunk_bytes_, static_cast<std::size_t>(threads_) * kChunksPerThread);
  // Each cut at the first module start at or after its place (cut_fraction):
  // a start the last pass noted, if one lies close enough, or one reached
  // by walking from the last start known before it.
  const std::vector<std::size_t>& known = string_.known_module_starts();
  const bool use_known = src.data == string_.data() && src.begin == 0;
  std::vector<std::size_t> starts{src.begin};
  std::size_t pos = src.begin;
  for (std::size_t c = 1; c < chunks; ++c) {
    const std::size_t target =
        src.begin + static_cast<std::size_t>(static_cast<double>(bytes) * cut_fraction(c, chunks));
    if (use_known && pos < target) {
      const auto after = std::lower_bound(known.begin(), known.end(), target);
      if (after != known.end() && *after - target < known_start_spacing()) pos = *after;
      else if (after != known.begin()) pos = std::max(pos, *std::prev(after));
    }
    while (pos < target) pos = src.next(pos);
    if (pos >= src.end) break;
    if (pos > starts.back()) starts.push_back(pos);
  }
  return starts;
}

bool Derivation::derive_forward_in_parallel() {
  if (!forward_parallel_ || tracking_births_) return false;
  const StringView src = current_view();
  const std::vector<std::size_t> starts = chunk_starts(src);
  if (starts.size() < 2) return false;
  if (branches_ready_ && branches_needed_)
    branches_.build_in_parts(starts, [&](std::size_t n, const std::function<void(std::size_t)>& task) {
      run_tasks(threads_, n, task);
    });
  const double growth = growth_.for_windows();
  run_in_chunks(src, starts, growth, [&](std::size_t, std::size_t from, std::size_t to, ModuleString& out) {
    return forward_range(src, from, to, out);
  });
  return true;
}

bool Derivation::decompose_in_parallel(int max_depth) {
  if (!decomposition_parallel_ || tracking_births_) return false;
  const StringView src = current_view();
  const std::vector<std::size_t> starts = chunk_starts(src);
  if (starts.size() < 2) return false;
  std::vector<Expansion> expansions(starts.size());
  const double growth = decomposition_growth_.for_windows();
  run_in_chunks(src, starts, growth, [&](std::size_t c, std::size_t from, std::size_t to, ModuleString& out) {
    Expansion& expansion = expansions[c];
    expansion.defer_warnings = true;
    expansion.depth_reached.clear();
    keyed_random::key = {};
    return expand(abi::RuleKind::Decomposition, src, 0, max_depth, out, expansion, to, from);
  });
  // The warnings of the chunks, in the order a serial pass meets them.
  for (const Expansion& expansion : expansions)
    for (ModuleId id : expansion.depth_reached) warn_depth_reached(abi::RuleKind::Decomposition, id, max_depth);
  return true;
}

void Derivation::run_in_chunks(const StringView& src, const std::vector<std::size_t>& starts, double growth,
                               const RangePass& range) {
  const std::size_t n = starts.size();
  auto end_of = [&](std::size_t c) { return c + 1 < n ? starts[c + 1] : src.end; };
  // Each chunk writes its successors straight into next_, in a window sized
  // by `growth`, with room for chunks growing unevenly as they did in the
  // last parallel pass, and a tenth more. A chunk that outgrows its window
  // goes on in a buffer of its own, at the cost of a copy; room to spare
  // costs too: the parts after it move down over it when they are joined,
  // faulting in the pages it left empty. Measured on the benchmark models, a
  // tenth costs least in all (2 and 25 percent were tried).
  constexpr std::size_t kPage = 4096;
  auto expected = [&](std::size_t c) { return static_cast<double>(end_of(c) - starts[c]) * growth; };
  std::vector<std::size_t> window(n + 1, 0);
  for (std::size_t c = 0; c < n; ++c) {
    const double room = expected(c) * chunk_growth_spread_ * 1.1 + kPage;
    window[c + 1] = window[c] + (static_cast<std::size_t>(room) + kPage - 1) / kPage * kPage;
  }
  next_.reserve_unwritten(window[n]);
  const std::size_t ready = next_.ready_bytes();  // faulted in by earlier passes
  if (chunk_out_.size() < n) chunk_out_.resize(n);
  struct Chunk {
    ModuleString& out;
    std::size_t reached = 0;  // where its pass stopped: at or past the next chunk's start
    std::exception_ptr failure = nullptr;
  };
  std::vector<Chunk> chunks;
  chunks.reserve(n);
  for (std::size_t c = 0; c < n; ++c) {
    chunk_out_[c].string.write_into(next_.data_for_writing() + window[c], window[c + 1] - window[c],
                                    ready > window[c] ? ready - window[c] : 0);
    chunks.push_back(Chunk{chunk_out_[c].string});
  }
  auto rewrite = [&](std::size_t c, std::size_t from) {
    Chunk& chunk = chunks[c];
    chunk.out.clear();
    chunk.failure = nullptr;
    try {
      chunk.reached = range(c, from, end_of(c), chunk.out);
    } catch (...) {
      chunk.failure = std::current_exception();
    }
  };
  // The parts are joined in order as the chunks before them are done, by
  // whichever thread finishes a chunk while no other is joining, so most of
  // the moving happens while later chunks are still being rewritten. A part
  // joins early only where the serial join below would leave it as it is:
  // its chunk ended in its window without failing, and began where the one
  // before it stopped. The first part that cannot stops the early joins.
  std::vector<std::size_t> place(n + 1, 0);  // where each part goes in next_
  unsigned char* data = next_.data_for_writing();
  std::mutex joining;
  std::vector<bool> done(n, false);
  std::size_t joined = 0;  // parts [0, joined) are in place
  bool a_thread_joins = false;
  // Where a part moves to outside the pages its chunk faulted in: faulted
  // in with one call, as growing strings are, not page by page by the move.
  auto fault_in_destination = [&](std::size_t c) {
    const ModuleString& part = chunks[c].out;
    const std::size_t own_end = window[c] + (part.writes_in_window() ? part.ready_bytes() : 0);
    if (place[c] < window[c]) next_.fault_in(place[c], std::min(place[c + 1], window[c]));
    if (place[c + 1] > own_end) next_.fault_in(std::max(place[c], own_end), place[c + 1]);
  };
  // Part `c` moved to its place, from its window or the buffer it spilled into.
  auto move = [&](std::size_t c) {
    fault_in_destination(c);
    const ModuleString& part = chunks[c].out;
    const unsigned char* from = part.writes_in_window() ? data + window[c] : part.data();
    if (part.size_bytes() && from != data + place[c]) std::memmove(data + place[c], from, part.size_bytes());
  };
  auto joins_early = [&](std::size_t c) {
    return !chunks[c].failure && chunks[c].out.writes_in_window() && (c == 0 || chunks[c - 1].reached == starts[c]);
  };
  auto finish = [&](std::size_t c) {
    std::unique_lock<std::mutex> lock(joining);
    done[c] = true;
    if (a_thread_joins) return;
    a_thread_joins = true;
    while (joined < n && done[joined] && joins_early(joined)) {
      const std::size_t j = joined;
      place[j + 1] = place[j] + chunks[j].out.size_bytes();
      lock.unlock();
      move(j);
      lock.lock();
      joined = j + 1;
    }
    a_thread_joins = false;
  };
  run_tasks(threads_, n, [&](std::size_t c) {
    rewrite(c, starts[c]);
    finish(c);
  });
  // A chunk whose first modules the one before rewrote (a predecessor of
  // several modules, or a cut, across the boundary) is rewritten again from
  // where that one stopped, as a serial pass would go on. A failure is the
  // serial pass's only where that pass would have got to it.
  double spread = 1;
  for (std::size_t c = 0; c < n; ++c) {
    if (c > 0 && chunks[c - 1].reached != starts[c]) {
      if (chunks[c - 1].reached >= end_of(c)) {
        chunks[c].out.clear();
        chunks[c].failure = nullptr;
        chunks[c].reached = chunks[c - 1].reached;
      } else {
        rewrite(c, chunks[c - 1].reached);
      }
    }
    if (chunks[c].failure) std::rethrow_exception(chunks[c].failure);
    place[c + 1] = place[c] + chunks[c].out.size_bytes();
    if (expected(c) > kPage)
      spread = std::max(spread, static_cast<double>(chunks[c].out.size_bytes()) / expected(c));
  }
  chunk_growth_spread_ = std::min(spread, 4.0);
  const std::size_t total = place[n];
  next_.reserve_unwritten_keeping(total);  // where the parts outgrew the windows
  // The parts not joined yet moved into place: those moving down first,
  // lowest first; then those moving up, highest first; then those that left
  // their windows. Each then writes over nothing that has yet to move.
  data = next_.data_for_writing();
  for (std::size_t c = joined; c < n; ++c)
    if (chunks[c].out.writes_in_window() && place[c] <= window[c]) move(c);
  for (std::size_t c = n; c-- > joined;)
    if (chunks[c].out.writes_in_window() && place[c] > window[c]) move(c);
  for (std::size_t c = joined; c < n; ++c)
    if (!chunks[c].out.writes_in_window()) move(c);
  // Where the pages faulted in end now: past the windows the chunks filled
  // in order from there.
  std::size_t faulted = ready;
  for (std::size_t c = 0; c < n && window[c] <= faulted; ++c)
    if (chunks[c].out.writes_in_window()) faulted = std::max(faulted, window[c] + chunks[c].out.ready_bytes());
  next_.set_written_size(total, faulted);
  // The starts the chunks noted, and where they joined, for the next pass.
  std::vector<std::size_t> known;
  for (std::size_t c = 0; c < n; ++c) {
    if (place[c] == place[c + 1]) continue;
    if (known.empty() || known.back() < place[c]) known.push_back(place[c]);
    for (std::size_t start : chunks[c].out.known_module_starts())
      if (place[c] + start > known.back()) known.push_back(place[c] + start);
  }
  next_.set_known_module_starts(std::move(known));
}

}  // namespace sylva::derive
