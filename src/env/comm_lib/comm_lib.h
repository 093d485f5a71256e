/* The Virtual Laboratory's communication library (EnviroManual section 4),
 * for environmental programs that Sylva runs as separate processes.
 *
 * Programs written for the Virtual Laboratory compile against this header
 * unchanged and link with libsylva_comm.a (C, no other dependency). The
 * library speaks Sylva's line protocol on the program's standard input and
 * output (docs/environment.md); anything the program itself prints to
 * standard output goes to standard error instead, so it cannot corrupt the
 * exchange.
 */
#ifndef SYLVA_COMM_LIB_H
#define SYLVA_COMM_LIB_H

#ifdef __cplusplus
extern "C" {
#endif

#define CMAXPARAMS 20   /* max. number of module parameters */
#define CMAXSYMBOLLEN 4 /* max. length of a module name; longer names are cut */

/* The turtle at a communication module. A count (nameC) is the number of
 * values the .e file asks for; 0 when the field is not sent. */
struct CTURTLE {
  float position[3];
  int positionC;
  float heading[3];
  int headingC;
  float left[3];
  int leftC;
  float up[3];
  int upC;
  float line_width;
  int line_widthC;
  float scale_factor;
  int scale_factorC;
};
typedef struct CTURTLE CTURTLE;

/* A communication module, or the module following it. */
struct module_type {
  char symbol[CMAXSYMBOLLEN + 1]; /* module name; "" when there is none */
  int num_params;                 /* number of parameters */
  struct param_type {
    float value; /* parameter value */
    char set;    /* 1, if modified (only those are sent back) */
  } params[CMAXPARAMS];
};
typedef struct module_type Cmodule_type;

/* Both modes. CSInitialize must come first in main(): it connects to the
 * modeling program and removes the library's options ("-e commfile.e") from
 * the command line. CTerminate comes last. */
void CSInitialize(int *argc, char ***argv);
void CTerminate(void);

/* Immediate answer mode: Answer is called for every communication module
 * (two_modules[0]; two_modules[1] is the module after it when the .e file
 * asks for it) and returns nonzero to send back the parameters it marked set.
 * Returns when the modeling program asks the process to exit. */
void CSMainLoop(int (*Answer)(Cmodule_type *two_modules, CTURTLE *turtle));

/* Delayed answer mode, in this order for each environmental pass:
 * CSBeginTransmission; CSGetData (and CSGetString) until it returns 0;
 * CSSendData for each module to answer; CSEndTransmission, which returns 1
 * when the process should exit. master is always 0. */
int CSBeginTransmission(void);
int CSGetData(int *master, unsigned long *module_id, Cmodule_type *two_modules, CTURTLE *turtle);
int CSGetString(int *master, char *str, int length);
void CSSendData(int master, unsigned long module_id, Cmodule_type *comm_module);
int CSEndTransmission(void);

#ifdef __cplusplus
}
#endif

#endif /* SYLVA_COMM_LIB_H */
