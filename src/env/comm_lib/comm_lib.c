/* The program's side of Sylva's environment protocol (docs/environment.md). */
#define _POSIX_C_SOURCE 200809L

#include "comm_lib.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define GREETING "sylva-environment 1"

enum { FIELD_POSITION, FIELD_HEADING, FIELD_LEFT, FIELD_UP, FIELD_LINE_WIDTH, FIELD_SCALE_FACTOR, FIELD_COUNT };
static const char *const field_names[FIELD_COUNT] = {"position", "heading", "left", "up", "line-width",
                                                     "scale-factor"};

static FILE *from_model; /* the protocol's input (the process's standard input) */
static FILE *to_model;   /* the protocol's output (the process's standard output as it was) */
static char *formats[FIELD_COUNT];
static unsigned long current_step;
static int exit_requested;
static int in_pass; /* the pass's queries are not all read yet */

/* One line of lookahead. */
static char *line;
static size_t line_capacity;
static int line_ready;

static void fatal(const char *what) {
  fprintf(stderr, "comm_lib: %s\n", what);
  exit(1);
}

/* The next line without its newline, or NULL at the end of input. */
static const char *peek_line(void) {
  if (!line_ready) {
    ssize_t n = getline(&line, &line_capacity, from_model);
    if (n < 0) return NULL;
    while (n > 0 && (line[n - 1] == '\n' || line[n - 1] == '\r')) line[--n] = '\0';
    line_ready = 1;
  }
  return line;
}

static void consume_line(void) { line_ready = 0; }

static int starts_with(const char *text, const char *word) {
  size_t n = strlen(word);
  return strncmp(text, word, n) == 0 && (text[n] == ' ' || text[n] == '\0');
}

/* The values in `text`, printed with `format`: literal characters are
 * skipped over (blanks match any blanks), each conversion reads a number. */
static int scan_with_format(const char *format, const char *text, float *values, int max_values) {
  int count = 0;
  const char *f = format, *t = text;
  while (*f && count < max_values) {
    if (*f == '%' && f[1] == '%') {
      if (*t == '%') ++t;
      f += 2;
    } else if (*f == '%') {
      char *end;
      double v;
      ++f;
      while (*f && !isalpha((unsigned char)*f)) ++f; /* flags, width, precision */
      if (*f) ++f;
      while (isspace((unsigned char)*t)) ++t;
      v = strtod(t, &end);
      if (end == t) break;
      values[count++] = (float)v;
      t = end;
    } else if (isspace((unsigned char)*f)) {
      while (isspace((unsigned char)*f)) ++f;
      while (isspace((unsigned char)*t)) ++t;
    } else {
      if (*t == *f) ++t;
      ++f;
    }
  }
  return count;
}

/* "SYMBOL N p1 ... pN" into a module. */
static void parse_module(const char *text, Cmodule_type *module) {
  char symbol[64];
  int n = 0, k, used = 0;
  memset(module, 0, sizeof *module);
  if (sscanf(text, " %63s %d%n", symbol, &n, &used) < 2) return;
  strncpy(module->symbol, symbol, CMAXSYMBOLLEN);
  module->symbol[CMAXSYMBOLLEN] = '\0';
  text += used;
  for (k = 0; k < n; ++k) {
    char *end;
    double v = strtod(text, &end);
    if (end == text) break;
    if (k < CMAXPARAMS) module->params[k].value = (float)v;
    text = end;
  }
  module->num_params = k < CMAXPARAMS ? k : CMAXPARAMS;
}

static void send_line(const char *text) {
  fputs(text, to_model);
  fputc('\n', to_model);
}

void CSInitialize(int *argc, char ***argv) {
  int in_fd = dup(STDIN_FILENO), out_fd = dup(STDOUT_FILENO);
  const char *first;
  int k, kept;
  if (in_fd < 0 || out_fd < 0) fatal("cannot take over standard input and output");
  from_model = fdopen(in_fd, "r");
  to_model = fdopen(out_fd, "w");
  if (!from_model || !to_model) fatal("cannot take over standard input and output");
  /* What the program prints on its own goes to standard error. */
  dup2(STDERR_FILENO, STDOUT_FILENO);

  first = peek_line();
  if (!first || strcmp(first, GREETING) != 0)
    fatal("this program is an environment for Sylva: it is started by 'sylva run' with a .e file, which speaks "
          "to it over its standard input and output");
  consume_line();
  for (;;) {
    const char *text = peek_line();
    if (!text) fatal("the modeling program closed the connection");
    if (strcmp(text, "end-header") == 0) {
      consume_line();
      break;
    }
    if (starts_with(text, "format")) {
      for (k = 0; k < FIELD_COUNT; ++k) {
        size_t n = strlen(field_names[k]);
        if (strncmp(text + 7, field_names[k], n) == 0 && text[7 + n] == ' ') {
          free(formats[k]);
          formats[k] = strdup(text + 8 + n);
        }
      }
    }
    /* following-module, verbose and lines of later versions: nothing to keep. */
    consume_line();
  }

  /* Drop "-e commfile.e": the communication file is the modeling program's. */
  if (argc && argv && *argv) {
    kept = 1;
    for (k = 1; k < *argc; ++k) {
      if (strcmp((*argv)[k], "-e") == 0 && k + 1 < *argc) {
        ++k;
        continue;
      }
      (*argv)[kept++] = (*argv)[k];
    }
    (*argv)[kept] = NULL;
    *argc = kept;
  }

  send_line("ready");
  fflush(to_model);
}

void CTerminate(void) {
  int k;
  if (to_model) fflush(to_model);
  for (k = 0; k < FIELD_COUNT; ++k) {
    free(formats[k]);
    formats[k] = NULL;
  }
  free(line);
  line = NULL;
  line_capacity = 0;
  line_ready = 0;
}

int CSBeginTransmission(void) {
  for (;;) {
    const char *text = peek_line();
    if (!text || strcmp(text, "exit") == 0) {
      exit_requested = 1;
      return 1;
    }
    consume_line();
    if (starts_with(text, "begin")) {
      current_step = strtoul(text + 5, NULL, 10);
      in_pass = 1;
      return 1;
    }
  }
}

int CSGetData(int *master, unsigned long *module_id, Cmodule_type *two_modules, CTURTLE *turtle) {
  const char *text;
  char *end;
  if (master) *master = 0;
  if (exit_requested || !in_pass) {
    if (module_id) *module_id = current_step;
    return 0;
  }
  /* Skip what the program did not read of the previous module (strings). */
  while ((text = peek_line()) != NULL && starts_with(text, "string")) consume_line();
  if (!text) {
    exit_requested = 1;
    *module_id = current_step;
    return 0;
  }
  if (strcmp(text, "end") == 0) {
    consume_line();
    in_pass = 0;
    *module_id = current_step;
    return 0;
  }
  if (!starts_with(text, "query")) fatal("unexpected line from the modeling program");
  memset(turtle, 0, sizeof *turtle);
  turtle->scale_factor = 1;
  memset(&two_modules[1], 0, sizeof two_modules[1]);
  *module_id = strtoul(text + 5, &end, 10);
  parse_module(end, &two_modules[0]);
  consume_line();

  while ((text = peek_line()) != NULL) {
    int k, matched = 0;
    if (starts_with(text, "following")) {
      parse_module(text + 9, &two_modules[1]);
      consume_line();
      continue;
    }
    for (k = 0; k < FIELD_COUNT; ++k) {
      if (!starts_with(text, field_names[k])) continue;
      const char *values = text + strlen(field_names[k]);
      if (*values == ' ') ++values;
      const char *format = formats[k] ? formats[k] : "%g %g %g";
      switch (k) {
        case FIELD_POSITION: turtle->positionC = scan_with_format(format, values, turtle->position, 3); break;
        case FIELD_HEADING: turtle->headingC = scan_with_format(format, values, turtle->heading, 3); break;
        case FIELD_LEFT: turtle->leftC = scan_with_format(format, values, turtle->left, 3); break;
        case FIELD_UP: turtle->upC = scan_with_format(format, values, turtle->up, 3); break;
        case FIELD_LINE_WIDTH: turtle->line_widthC = scan_with_format(format, values, &turtle->line_width, 1); break;
        default: turtle->scale_factorC = scan_with_format(format, values, &turtle->scale_factor, 1); break;
      }
      matched = 1;
      break;
    }
    if (!matched) break; /* the next query, a string or the end */
    consume_line();
  }
  return 1;
}

int CSGetString(int *master, char *str, int length) {
  const char *text;
  if (master) *master = 0;
  if (exit_requested || !in_pass) return 0;
  text = peek_line();
  if (!text || !starts_with(text, "string")) return 0;
  text += 6;
  if (*text == ' ') ++text;
  if (length > 0) {
    strncpy(str, text, (size_t)length - 1);
    str[length - 1] = '\0';
  }
  consume_line();
  return 1;
}

void CSSendData(int master, unsigned long module_id, Cmodule_type *comm_module) {
  int k, n = comm_module->num_params;
  (void)master;
  if (n > CMAXPARAMS) n = CMAXPARAMS;
  for (k = 0; k < n; ++k)
    if (comm_module->params[k].set)
      fprintf(to_model, "%lu %d %.9g\n", module_id, k, (double)comm_module->params[k].value);
}

int CSEndTransmission(void) {
  const char *text;
  if (exit_requested) return 1;
  /* Whatever is left of this pass was not asked for. */
  while (in_pass) {
    text = peek_line();
    if (!text) {
      exit_requested = 1;
      return 1;
    }
    if (strcmp(text, "end") == 0) in_pass = 0;
    consume_line();
  }
  send_line("end");
  fflush(to_model);
  /* Wait for the next pass, or the request to exit. */
  text = peek_line();
  if (!text || strcmp(text, "exit") == 0) {
    exit_requested = 1;
    return 1;
  }
  return 0;
}

void CSMainLoop(int (*Answer)(Cmodule_type *two_modules, CTURTLE *turtle)) {
  Cmodule_type two_modules[2];
  CTURTLE turtle;
  unsigned long module_id;
  int master;
  char ignored[256];
  for (;;) {
    CSBeginTransmission();
    if (exit_requested) return;
    while (CSGetData(&master, &module_id, two_modules, &turtle)) {
      while (CSGetString(&master, ignored, (int)sizeof ignored)) {
      }
      if (Answer(two_modules, &turtle)) CSSendData(master, module_id, &two_modules[0]);
    }
    /* Answers go out as they are made, so the modeling program is never kept waiting. */
    fflush(to_model);
    if (CSEndTransmission()) return;
  }
}
