#include "studio/panel_file.h"

#include <algorithm>
#include <charconv>
#include <optional>

#include "studio/text_lines.h"
#include "support/diagnostic.h"

namespace sylva::studio {

namespace {

// One "keyword: value" line; both parts without surrounding blanks.
struct Entry {
  std::string_view key;
  std::string_view value;
  int line = 0;
  int key_column = 0;
  int value_column = 0;
};

std::optional<Entry> entry_of(const TextLine& line) {
  const std::size_t colon = line.text.find(':');
  if (colon == std::string_view::npos) return std::nullopt;
  const std::string_view key = trim_blanks(line.text.substr(0, colon));
  const std::string_view value = trim_blanks(line.text.substr(colon + 1));
  const auto column_of = [&](std::string_view part, std::size_t fallback) {
    return static_cast<int>((part.empty() ? fallback : part.data() - line.text.data()) + 1);
  };
  return Entry{key, value, line.number, column_of(key, 0), column_of(value, colon + 1)};
}

struct KindInfo {
  PanelItemKind kind;
  std::string_view word;
  std::vector<std::string_view> allowed;
  std::vector<std::string_view> required;
};

// The keywords each kind of block may hold (any order) and those it must.
const KindInfo kKinds[] = {
    {PanelItemKind::Slider, "SLIDER", {"name", "colors", "origin", "min/max", "value", "message"},
     {"name", "min/max", "value", "message"}},
    {PanelItemKind::Button, "BUTTON", {"name", "colors", "tricolor", "origin", "value", "message"},
     {"name", "value", "message"}},
    {PanelItemKind::Group, "GROUP", {}, {}},
    {PanelItemKind::Label, "LABEL", {"name", "color", "origin"}, {"name"}},
    {PanelItemKind::Menu, "MENU", {"name", "message"}, {"name", "message"}},
    {PanelItemKind::Page, "PAGE", {"name", "color", "origin", "message"}, {"name"}},
};

const std::vector<std::string_view> kHeaderKeys = {"target", "panel name", "background", "size", "font", "colourmap"};

std::string listed(const std::vector<std::string_view>& words) {
  std::string text;
  for (std::string_view word : words) text.append(text.empty() ? "" : ", ").append(word).append(":");
  return text;
}

bool contains(const std::vector<std::string_view>& words, std::string_view word) {
  return std::find(words.begin(), words.end(), word) != words.end();
}

class PanelReader {
 public:
  PanelReader(std::string_view text, const std::string& file_name) : file_(file_name) {
    for (const TextLine& line : split_lines(text))
      if (!trim_blanks(line.text).empty()) lines_.push_back(line);
  }

  PanelFile read() {
    read_header();
    while (next_ < lines_.size()) read_item();
    return std::move(panel_);
  }

 private:
  [[noreturn]] void fail(int line, int column, const std::string& message) const {
    throw ModelError(SourceLocation{file_, line, column}, message);
  }

  Entry entry_at(std::size_t index) const {
    std::optional<Entry> entry = entry_of(lines_[index]);
    if (!entry) fail(lines_[index].number, 1, "expected 'keyword: value'");
    return *entry;
  }

  bool at_type_line() const {
    if (next_ >= lines_.size()) return false;
    const std::optional<Entry> entry = entry_of(lines_[next_]);
    return entry && entry->key == "type";
  }

  void read_header() {
    bool named = false;
    while (next_ < lines_.size() && !at_type_line()) {
      const Entry entry = entry_at(next_++);
      if (!contains(kHeaderKeys, entry.key))
        fail(entry.line, entry.key_column,
             "expected a panel header keyword (" + listed(kHeaderKeys) + "), found '" + std::string(entry.key) + ":'");
      if (entry.key == "panel name") {
        panel_.name = entry.value;
        named = true;
      } else if (entry.key == "target") {
        panel_.target = entry.value;
      }
    }
    if (!named) fail(next_ < lines_.size() ? lines_[next_].number : 1, 1, "expected 'panel name:' in the panel header");
  }

  void read_item() {
    const Entry type = entry_at(next_++);
    const KindInfo* info = nullptr;
    for (const KindInfo& candidate : kKinds)
      if (candidate.word == type.value) info = &candidate;
    if (!info)
      fail(type.line, type.value_column,
           "expected SLIDER, BUTTON, GROUP, LABEL, MENU or PAGE, found '" + std::string(type.value) + "'");

    PanelItem item;
    item.kind = info->kind;
    item.line = type.line;
    if (info->kind == PanelItemKind::Group) {
      read_group_buttons(item);
    } else {
      read_fields(*info, item);
    }
    item.display_name = item.name.substr(0, item.name.find('%'));

    if (item.kind == PanelItemKind::Page) {
      panel_.pages.push_back(item.display_name);
    } else if (panel_.pages.empty()) {
      panel_.pages.emplace_back();
    }
    item.page = static_cast<int>(panel_.pages.size()) - 1;
    panel_.items.push_back(std::move(item));
  }

  // A group lists its buttons' names, one a line, after an optional colour,
  // up to a line "ENDGROUP".
  void read_group_buttons(PanelItem& group) {
    if (next_ < lines_.size() && trim_blanks(lines_[next_].text).starts_with("color:")) ++next_;
    for (; next_ < lines_.size(); ++next_) {
      const std::string_view name = trim_blanks(lines_[next_].text);
      if (name == "ENDGROUP") {
        ++next_;
        return;
      }
      group.buttons.emplace_back(name);
    }
    fail(group.line, 1, "expected 'ENDGROUP' to close the GROUP that begins here");
  }

  void read_fields(const KindInfo& info, PanelItem& item) {
    std::vector<Entry> fields;
    while (next_ < lines_.size() && !at_type_line()) {
      const Entry entry = entry_at(next_++);
      if (!contains(info.allowed, entry.key))
        fail(entry.line, entry.key_column,
             "expected " + listed(info.allowed) + " or type: in a " + std::string(info.word) + ", found '" +
                 std::string(entry.key) + ":'");
      for (const Entry& earlier : fields)
        if (earlier.key == entry.key)
          fail(entry.line, entry.key_column,
               "a second '" + std::string(entry.key) + ":' in one " + std::string(info.word) +
                   " (expected 'type:' to begin the next item)");
      fields.push_back(entry);
    }
    for (std::string_view key : info.required)
      if (std::none_of(fields.begin(), fields.end(), [&](const Entry& e) { return e.key == key; }))
        fail(item.line, 1,
             "expected a '" + std::string(key) + ":' line in the " + std::string(info.word) + " that begins here");

    for (const Entry& field : fields) {
      if (field.key == "name") {
        item.name = field.value;
      } else if (field.key == "message") {
        item.message = field.value;
        item.message_line = field.line;
        item.message_column = field.value_column;
      } else if (field.key == "min/max") {
        const std::vector<int> bounds = integers(field, 2);
        item.min = bounds[0];
        item.max = bounds[1];
      } else if (field.key == "value") {
        item.value = integers(field, 1)[0];
      }
    }
  }

  std::vector<int> integers(const Entry& entry, std::size_t count) const {
    const std::vector<std::string_view> words = split_words(entry.value);
    std::vector<int> values(words.size());
    bool well_formed = words.size() == count;
    for (std::size_t i = 0; well_formed && i < words.size(); ++i) {
      const char* end = words[i].data() + words[i].size();
      const auto [stop, error] = std::from_chars(words[i].data(), end, values[i]);
      well_formed = error == std::errc() && stop == end;
    }
    if (!well_formed)
      fail(entry.line, entry.value_column,
           std::string("expected ") + (count == 1 ? "an integer" : std::to_string(count) + " integers") + " after '" +
               std::string(entry.key) + ":'");
    return values;
  }

  const std::string& file_;
  std::vector<TextLine> lines_;  // the non-blank ones
  std::size_t next_ = 0;
  PanelFile panel_;
};

}  // namespace

PanelFile read_panel(std::string_view text, const std::string& file_name) {
  return PanelReader(text, file_name).read();
}

bool looks_like_panel(std::string_view text) {
  std::vector<std::optional<Entry>> first_two;
  for (const TextLine& line : split_lines(text)) {
    if (trim_blanks(line.text).empty()) continue;
    first_two.push_back(entry_of(line));
    if (first_two.size() == 2) break;
  }
  const auto is = [&](std::size_t index, std::string_view key) {
    return index < first_two.size() && first_two[index] && first_two[index]->key == key;
  };
  return is(0, "panel name") || (is(0, "target") && is(1, "panel name"));
}

}  // namespace sylva::studio
