/* The delayed answer environmental program of EnviroManual section 4.3.2,
 * compiled against Sylva's comm_lib.h as printed, except for its misprints:
 *  - DetermineResponse answered a collision with 0 ("report only
 *    collisions"), which the model cannot tell from no answer; the text
 *    says the environment sets the parameter to 1, so it does here;
 *  - fabs(queries[i].position[1] - queries[j].position[1] < EPSILON) had its
 *    closing parenthesis after EPSILON; it is now before the comparison;
 *  - the comments' "don?t" and "?exit?" lost their quotes in printing.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "comm_lib.h"
#define EPSILON 0.001 /* precision of comparisons */
#define MAXQUERIES 1000 /* maximum number of queries */

struct item_type {
     float position[2];
     float query;
     unsigned long id;
     int master;
} queries[MAXQUERIES]; /* queries */
int num_queries; /* actual number of stored queries */

/************************************************************/
void StoreQuery(int master, unsigned long module_id,
                           Cmodule_type *comm_symbol, CTURTLE *tu)
{
     if (tu->positionC < 2) {
          /* do not write to stdout, because it is used for pipes */
          fprintf(stderr,"environment: turtle position missing.\n");
          return;
     }
     if (num_queries >= MAXQUERIES) {
          fprintf(stderr, "environment: too many queries!\n");
          return;
     }
     queries[num_queries].position[0] = tu->position[0];
     queries[num_queries].position[1] = tu->position[1];
     queries[num_queries].query = comm_symbol->num_params >= 1;
     /* answer only if ?E has one or more parameters */
     queries[num_queries].master = master;
     queries[num_queries].id = module_id;
     num_queries++;
}

/************************************************************/
void DetermineResponse(void)
{
     int i, j;
     Cmodule_type comm_symbol;

     comm_symbol.num_params = 1;
     comm_symbol.params[0].set = 1;
     comm_symbol.params[0].value = 1; /* report only collisions */
     for (i=0; i< num_queries; i++) /* for all queries */
          if(queries[i].query) { /* don't answer if no parameter */
               for (j=0; j<num_queries; j++)
                   if (i!=j)
                            if (fabs(queries[i].position[0]
                                    - queries[j].position[0]) < EPSILON &&
                                fabs(queries[i].position[1]
                                     - queries[j].position[1]) < EPSILON) {
                                 CSSendData(queries[i].master,queries[i].id,
                                     &comm_symbol);
                                 break;
                            }
            }
}

/************************************************************/
void MainLoop(void)
{ /* controls the loop of data exchange */
     Cmodule_type two_modules[2];
     unsigned long module_id;
     int master;
     CTURTLE turtle;

      /* infinite loop - until message "exit" comes */
      for(;;) {
           CSBeginTransmission();
           num_queries = 0;
           while (CSGetData(&master,&module_id,two_modules,&turtle))
                StoreQuery(master, module_id, two_modules, &turtle);
           DetermineResponse();

            /* EndTransmission returns 1 when the process is
                    requested to exit */
            if (CSEndTransmission())
                 break;
      }
}

/************************************************************/
int main(int argc, char **argv)
{
     /* initialize the communication as the very first thing */
     CSInitialize(&argc, &argv);
     MainLoop();
     CTerminate(); /* should be the last function called */
     return 1;
}
