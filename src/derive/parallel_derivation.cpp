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
#include <memory>
#include <mutex>

#include "derive/chunk_output_pool.h"
#include "derive/derivation.h"
#include "derive/keyed_random.h"
#include "derive/worker_threads.h"
#include "lstring/run_limits.h"

namespace sylva::derive {
namespace {

// Chunks per thread, at least: rewriting some parts of a string costs more
// than others.
constexpr std::size_t kChunksPerThread = 4;

// The successors of a chunk, about: written into a buffer of the chunk's
// own and copied into the next string from there (run_in_chunks), they stay
// in the core's cache, with room for the chunk's part of the old string
// (current x86 and Arm cores have 512 KiB to 2 MiB of L2). On two threads
// with 1 MiB of L2 each, koch's last step took about as long with parts of
// 512 KiB and 1 MiB (one run each).
constexpr std::size_t kPartBytes = std::size_t{256} << 10;

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

// Freeing a string's pages is the kernel's work, on the thread that frees
// it, while the others wait: at the end of a koch run, 24 ms for its two
// strings (250 MB). The pages of the strings, of the branch index and of the
// chunks' buffers (two for each thread, over a megabyte each) are given back
// in stretches on every thread first, and the freeing then finds none.
void Derivation::release_memory_in_parallel() {
  if (threads_ < 2) return;
  constexpr std::size_t kStretch = std::size_t{8} << 20;
  struct Stretch {
    page_memory::Pages pages;
    std::size_t from;
  };
  try {
    std::vector<page_memory::Pages> buffers = branches_.pages();
    for (const page_memory::Pages& pages : chunk_outputs_.pages()) buffers.push_back(pages);
    buffers.push_back(string_.faulted_in_pages());
    buffers.push_back(next_.faulted_in_pages());
    std::vector<Stretch> stretches;
    for (const page_memory::Pages& pages : buffers)
      for (std::size_t from = 0; from < pages.bytes; from += kStretch) stretches.push_back({pages, from});
    if (stretches.size() < 2) return;
    run_tasks(threads_, stretches.size(), [&](std::size_t k) {
      page_memory::release(stretches[k].pages, stretches[k].from, stretches[k].from + kStretch);
    });
  } catch (...) {
    // No memory or no thread to spare: the buffers are freed all the same.
  }
}

std::vector<std::size_t> Derivation::chunk_starts(const StringView& src, double growth) const {
  const std::size_t bytes = src.end - src.begin;
  if (threads_ < 2 || bytes < 2 * min_chunk_bytes_) return {};
  const auto parts = static_cast<std::size_t>(static_cast<double>(bytes) * growth) / kPartBytes;
  const std::size_t chunks =
      std::min(bytes / min_chunk_bytes_, std::max(static_cast<std::size_t>(threads_) * kChunksPerThread, parts));
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
  const double growth = growth_.for_parallel_pass();
  const std::vector<std::size_t> starts = chunk_starts(src, growth);
  if (starts.size() < 2) return false;
  if (branches_ready_ && branches_needed_)
    branches_.build_in_parts(starts, [&](std::size_t n, const std::function<void(std::size_t)>& task) {
      run_tasks(threads_, n, task);
    });
  run_in_chunks(src, starts, growth, [&](std::size_t, std::size_t from, std::size_t to, ModuleString& out) {
    return forward_range(src, from, to, out);
  });
  return true;
}

bool Derivation::decompose_in_parallel(int max_depth) {
  if (!decomposition_parallel_ || tracking_births_) return false;
  const StringView src = current_view();
  const double growth = decomposition_growth_.for_parallel_pass();
  const std::vector<std::size_t> starts = chunk_starts(src, growth);
  if (starts.size() < 2) return false;
  std::vector<Expansion> expansions(starts.size());
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
  // Each chunk writes its successors into a buffer of its own, small enough
  // to stay in its core's cache (chunk_starts), and the part is copied into
  // next_ once the chunks before it are done: where it goes is then known.
  // So next_ is written once, in order, as a serial pass writes it, and the
  // copy is cheap: the pages it writes, faulted in just before, are still
  // in the cache (6 ms of thread time in the last koch step, 191 MB, on two
  // threads). Writing the chunks straight into next_ instead, each in a
  // window at a guess of where its part goes, wrote every part but the
  // first twice, as the parts moved into place: 14.5 ms in that step.
  const std::size_t n = starts.size();
  auto end_of = [&](std::size_t c) { return c + 1 < n ? starts[c + 1] : src.end; };
  const double expected = static_cast<double>(src.end - src.begin) * growth;
  next_.reserve_unwritten(static_cast<std::size_t>(expected * 1.1));
  const std::size_t room = next_.reserved_bytes();
  const std::size_t ready = next_.ready_bytes();  // faulted in by earlier passes
  struct Chunk {
    std::unique_ptr<ChunkOutputPool::Output> out;
    std::size_t reached = 0;  // where its pass stopped: at or past the next chunk's start
    std::exception_ptr failure = nullptr;
    std::vector<std::size_t> noted;  // the module starts its part noted, once copied
    bool done = false;
  };
  std::vector<Chunk> chunks(n);
  // The chunks' outputs go back to the pool however the pass ends. Two for
  // each thread are kept: where a thread was held up, the others filled
  // more while their parts waited for its chunk.
  struct GiveBack {
    std::vector<Chunk>& chunks;
    ChunkOutputPool& pool;
    std::size_t kept;
    ~GiveBack() {
      for (Chunk& chunk : chunks)
        if (chunk.out) pool.give_back(std::move(chunk.out));
      pool.keep_at_most(kept);
    }
  } give_back{chunks, chunk_outputs_, 2 * static_cast<std::size_t>(threads_)};
  std::mutex placing;  // guards what follows
  std::vector<std::size_t> place(n + 1, 0);  // where each part goes in next_
  std::size_t placed = 0;  // parts [0, placed) have their places
  std::size_t claimed = 0;  // parts [0, claimed) are being or have been copied
  auto rewrite = [&](std::size_t c, std::size_t from) {
    Chunk& chunk = chunks[c];
    chunk.out->string.clear();  // a chunk rewritten again
    chunk.failure = nullptr;
    try {
      chunk.reached = range(c, from, end_of(c), chunk.out->string);
    } catch (...) {
      chunk.failure = std::current_exception();
    }
  };
  unsigned char* data = next_.data_for_writing();
  auto copy = [&](std::size_t c) {
    const ModuleString& part = chunks[c].out->string;
    if (part.empty()) return;
    next_.fault_in(std::max(place[c], ready), place[c + 1]);
    std::memcpy(data + place[c], part.data(), part.size_bytes());
    chunks[c].noted = part.known_module_starts();
  };
  // A part is placed during the pass where the serial join below would
  // place it as it is: its chunk did not fail, began where the one before
  // it stopped, and fits in the room reserved. The first part that cannot
  // stops the placing; it and those after it are joined after the pass.
  auto placeable = [&](std::size_t c) {
    const Chunk& chunk = chunks[c];
    return chunk.done && !chunk.failure && (c == 0 || chunks[c - 1].reached == starts[c]) &&
           place[c] + chunk.out->string.size_bytes() <= room;
  };
  run_tasks(threads_, n, [&](std::size_t c) {
    chunks[c].out = chunk_outputs_.take(
        static_cast<std::size_t>(static_cast<double>(end_of(c) - starts[c]) * growth * 1.1));
    rewrite(c, starts[c]);
    std::size_t first, last;  // the parts this thread copies
    {
      std::lock_guard<std::mutex> lock(placing);
      chunks[c].done = true;
      for (; placed < n && placeable(placed); ++placed)
        place[placed + 1] = place[placed] + chunks[placed].out->string.size_bytes();
      first = claimed;
      last = claimed = placed;
    }
    for (std::size_t k = first; k < last; ++k) {
      copy(k);
      chunk_outputs_.give_back(std::move(chunks[k].out));
    }
  });
  // A chunk whose first modules the one before rewrote (a predecessor of
  // several modules, or a cut, across the boundary) is rewritten again from
  // where that one stopped, as a serial pass would go on. A failure is the
  // serial pass's only where that pass would have got to it.
  for (std::size_t c = placed; c < n; ++c) {
    if (c > 0 && chunks[c - 1].reached != starts[c]) {
      if (chunks[c - 1].reached >= end_of(c)) {
        chunks[c].out->string.clear();
        chunks[c].failure = nullptr;
        chunks[c].reached = chunks[c - 1].reached;
      } else {
        rewrite(c, chunks[c - 1].reached);
      }
    }
    if (chunks[c].failure) std::rethrow_exception(chunks[c].failure);
    place[c + 1] = place[c] + chunks[c].out->string.size_bytes();
  }
  const std::size_t total = place[n];
  if (placed < n) {
    next_.reserve_unwritten_keeping(total);
    data = next_.data_for_writing();
    for (std::size_t c = placed; c < n; ++c) copy(c);
  }
  next_.set_written_size(total);
  // The starts the chunks noted, and where they joined, for the next pass.
  std::vector<std::size_t> known;
  for (std::size_t c = 0; c < n; ++c) {
    if (place[c] == place[c + 1]) continue;
    if (known.empty() || known.back() < place[c]) known.push_back(place[c]);
    for (std::size_t start : chunks[c].noted)
      if (place[c] + start > known.back()) known.push_back(place[c] + start);
  }
  next_.set_known_module_starts(std::move(known));
}

}  // namespace sylva::derive
