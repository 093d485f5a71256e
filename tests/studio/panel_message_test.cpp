// Panel messages and what awkped and ped do with them (VLAB Tools manual,
// 2.3 and 11.2); the expected texts follow the manual's own examples.
#include <gtest/gtest.h>

#include "studio/panel_message.h"

namespace sylva::studio {
namespace {

MessageTemplate message(std::string_view text) { return parse_message(text, {"panel.l", 9, 10}); }

std::string error_of(std::string_view text) {
  try {
    message(text);
  } catch (const ModelError& e) {
    return e.what();
  }
  return "no error";
}

TEST(PanelMessage, ParsesTheThreeForms) {
  const MessageTemplate define = message("d SIZE %d 10");
  EXPECT_EQ(define.form, MessageTemplate::Form::Define);
  EXPECT_EQ(define.define, "SIZE");
  EXPECT_FALSE(define.fixed_value.has_value());
  EXPECT_EQ(define.scale, 10);

  const MessageTemplate unscaled = message("d  X %d");  // the scale is optional
  EXPECT_EQ(unscaled.define, "X");
  EXPECT_EQ(unscaled.scale, 1);

  const MessageTemplate word = message("n 2 2 -1 %d");
  EXPECT_EQ(word.form, MessageTemplate::Form::Word);
  EXPECT_EQ(word.line, 2);
  EXPECT_EQ(word.word, 2);
  EXPECT_EQ(word.exponent, -1);

  const MessageTemplate scaled_word = message("5 1 %d 100");
  EXPECT_EQ(scaled_word.form, MessageTemplate::Form::ScaledWord);
  EXPECT_EQ(scaled_word.line, 5);
  EXPECT_EQ(scaled_word.word, 1);
  EXPECT_EQ(scaled_word.scale, 100);
}

TEST(PanelMessage, ButtonAndPageTemplatesMayCarryTheirOwnValue) {
  const MessageTemplate button = message("d LEFT 1 1");
  EXPECT_EQ(button.fixed_value, 1);
  EXPECT_EQ(message_value_text(button, 0), "1");  // the template's value wins
  EXPECT_EQ(message_value_text(message("d NOTHING %d 1"), 0), "0");
}

TEST(PanelMessage, ErrorsPointIntoTheTemplate) {
  EXPECT_EQ(error_of("x 1"), "panel.l:9:10: error: expected a message beginning with 'd', 'n' or a line number in "
                             "the message 'x 1'");
  EXPECT_EQ(error_of("d SIZE %d 0"),
            "panel.l:9:20: error: expected a scale (a number other than 0) after the value in the message 'd SIZE %d 0'");
  EXPECT_EQ(error_of("d <name> %d <scale>"),
            "panel.l:9:22: error: expected a scale (a number other than 0) after the value in the message "
            "'d <name> %d <scale>'");
  EXPECT_EQ(error_of("n 4 1 0"), "panel.l:9:17: error: expected %d or an integer value in the message 'n 4 1 0'");
  EXPECT_EQ(error_of("n 0 1 0 %d"), "panel.l:9:12: error: expected a line number after 'n' in the message 'n 0 1 0 %d'");
  EXPECT_EQ(error_of(""), "panel.l:9:10: error: expected a message ('d NAME %d SCALE' or 'n LINE WORD EXPONENT %d') "
                          "in the message ''");
}

TEST(PanelMessage, ValueTextsReadBackAsTheValueSent) {
  EXPECT_EQ(message_value_text(message("d SIZE %d 10"), 46), "4.6");  // the manual's example
  EXPECT_EQ(message_value_text(message("d SIZE %d"), 5), "5");
  EXPECT_EQ(message_value_text(message("d SIZE %d 1"), 40), "40");
  EXPECT_EQ(message_value_text(message("d SIZE %d 10"), 40), "4");
  EXPECT_EQ(message_value_text(message("d SIZE %d 100"), -5), "-0.05");
  EXPECT_EQ(message_value_text(message("d SIZE %d 10"), 0), "0");
  const std::string third = message_value_text(message("d SIZE %d 3"), 1);
  EXPECT_EQ(std::stod(third), 1.0 / 3);
  EXPECT_EQ(third, "0.3333333333333333");

  EXPECT_EQ(message_value_text(message("n 2 2 -1 %d"), 48), "4.8");  // 48 x 10^-1, the manual's example
  EXPECT_EQ(message_value_text(message("n 1 4 0 %d"), 5), "5");
  EXPECT_EQ(message_value_text(message("n 1 1 2 %d"), 5), "500");
  EXPECT_EQ(message_value_text(message("n 1 1 -3 %d"), 5), "0.005");
  EXPECT_EQ(message_value_text(message("n 1 1 -1 %d"), 50), "5");
  EXPECT_EQ(message_value_text(message("n 1 1 -2 %d"), -125), "-1.25");
  EXPECT_EQ(message_value_text(message("n 1 1 -2 %d"), 0), "0");
}

TEST(PanelMessage, AwkpedRewritesTheDefinesValueAndNothingElse) {
  // The manual: "#define SIZE 4" and "d SIZE 46 10" give 4.6.
  const FileEdit edit = apply_message("#define SIZE 4\n", message("d SIZE %d 10"), 46, ParameterEditor::Awkped);
  EXPECT_EQ(edit.text, "#define SIZE 4.6\n");
  EXPECT_EQ(edit.changed_lines, std::vector<int>{1});
  EXPECT_EQ(edit.problem, "");

  const std::string file =
      "/* plant */\r\n"
      "  #define\tSIZE   4   /* size of a leaf */\r\n"
      "#define SIZEX 4\r\n"
      "# define SIZE 4\r\n"
      "#define SIZE 7// again\r\n"
      "#define ANGLE 30";
  const FileEdit twice = apply_message(file, message("d SIZE %d 1"), 12, ParameterEditor::Awkped);
  EXPECT_EQ(twice.text,
            "/* plant */\r\n"
            "  #define\tSIZE   12   /* size of a leaf */\r\n"
            "#define SIZEX 4\r\n"
            "# define SIZE 4\r\n"
            "#define SIZE 12// again\r\n"
            "#define ANGLE 30");
  EXPECT_EQ(twice.changed_lines, (std::vector<int>{2, 5}));

  const FileEdit last_line = apply_message(file, message("d ANGLE %d 1"), 45, ParameterEditor::Awkped);
  EXPECT_EQ(last_line.text.substr(last_line.text.size() - 18), "\r\n#define ANGLE 45");

  EXPECT_EQ(set_define("#define FLAG\n", "FLAG", "1").text, "#define FLAG 1\n");
}

TEST(PanelMessage, ADefineNotFoundChangesNothingAndSaysSo) {
  const std::string file = "#define SIZE 4\n# define WIDTH 2\n";
  for (std::string_view name : {"WIDTH", "SIZ", "size"}) {
    const FileEdit edit = set_define(file, name, "5");
    EXPECT_EQ(edit.text, file);
    EXPECT_TRUE(edit.changed_lines.empty());
    EXPECT_EQ(edit.problem, "no line '#define " + std::string(name) + "' in the file");
  }
}

TEST(PanelMessage, AwkpedReplacesTheNthWordOfTheNthLine) {
  // The manual's example file and messages.
  const std::string file = "initial line width: 7 pixels\nsize: 4.2\n";
  const FileEdit width = apply_message(file, message("n 1 4 0 %d"), 5, ParameterEditor::Awkped);
  EXPECT_EQ(width.text, "initial line width: 5 pixels\nsize: 4.2\n");
  EXPECT_EQ(width.changed_lines, std::vector<int>{1});
  EXPECT_EQ(apply_message(file, message("n 2 2 -1 %d"), 48, ParameterEditor::Awkped).text,
            "initial line width: 7 pixels\nsize: 4.8\n");
  // A comma after the old word stays after the new one.
  EXPECT_EQ(apply_message("view: 1,  2, 3\n", message("n 1 3 0 %d"), 9, ParameterEditor::Awkped).text,
            "view: 1,  9, 3\n");
  EXPECT_EQ(apply_message("a 1 b\n", message("1 2 %d 10"), 46, ParameterEditor::Awkped).text, "a 4.6 b\n");

  const FileEdit past_words = apply_message(file, message("n 2 3 0 %d"), 5, ParameterEditor::Awkped);
  EXPECT_EQ(past_words.text, file);
  EXPECT_EQ(past_words.problem, "line 2 has no word 3");
  EXPECT_EQ(apply_message(file, message("n 3 1 0 %d"), 5, ParameterEditor::Awkped).problem, "the file has no line 3");
}

TEST(PanelMessage, PedReplacesTheNumberAfterTheColonOrACommaOfTheLine) {
  const std::string file = "double buffer: on\r\nswap interval: 10\r\nviewpoint: 0, 0,300\r\n";
  const FileEdit swap = apply_message(file, message("n 2 1 0 %d"), 2, ParameterEditor::Ped);
  EXPECT_EQ(swap.text, "double buffer: on\r\nswap interval: 2\r\nviewpoint: 0, 0,300\r\n");
  EXPECT_EQ(swap.changed_lines, std::vector<int>{2});
  EXPECT_EQ(apply_message(file, message("n 3 1 -1 %d"), 15, ParameterEditor::Ped).text,
            "double buffer: on\r\nswap interval: 10\r\nviewpoint: 1.5, 0,300\r\n");
  EXPECT_EQ(apply_message(file, message("n 3 2 0 %d"), -7, ParameterEditor::Ped).text,
            "double buffer: on\r\nswap interval: 10\r\nviewpoint: 0, -7,300\r\n");
  EXPECT_EQ(apply_message(file, message("n 3 3 2 %d"), 4, ParameterEditor::Ped).text,
            "double buffer: on\r\nswap interval: 10\r\nviewpoint: 0, 0,400\r\n");

  EXPECT_EQ(apply_message(file, message("n 2 2 0 %d"), 1, ParameterEditor::Ped).problem,
            "line 2 has no field 2 (a number after ':' or ',')");
  EXPECT_EQ(apply_message(file, message("n 2 4 0 %d"), 1, ParameterEditor::Ped).problem,
            "ped edits fields 1 to 3 only, not 4");
  const FileEdit define = apply_message("#define X 1\n", message("d X %d 1"), 2, ParameterEditor::Ped);
  EXPECT_EQ(define.text, "#define X 1\n");
  EXPECT_EQ(define.problem, "ped understands only 'n LINE FIELD EXPONENT VALUE' messages");
}

}  // namespace
}  // namespace sylva::studio
