/* The immediate answer environmental program of EnviroManual section 4.3.1,
 * compiled against Sylva's comm_lib.h, with its misprints mended:
 *  - "static float zero[3]=0,0,0;" lacked its braces;
 *  - Distance() was not defined: it is the Euclidean distance here;
 *  - turtle.position is turtle->position (turtle is a pointer);
 *  - main() returns int.
 */
#include <stdio.h>
#include <math.h>
#include "comm_lib.h"

static float Distance(const float *a, const float *b)
{
     return sqrtf((a[0]-b[0])*(a[0]-b[0]) + (a[1]-b[1])*(a[1]-b[1]) + (a[2]-b[2])*(a[2]-b[2]));
}

int Answer(Cmodule_type *two_modules, CTURTLE *turtle)
{
     static float zero[3]={0,0,0};

     if (turtle->positionC < 3) {
          fprintf(stderr,"Turtle position not set!\n");
          return 0;
     }
     if (two_modules[0].num_params >= 1) {
          two_modules[0].params[0].set = 1;    /* parameter modified */
          two_modules[0].params[0].value = Distance(turtle->position,zero)
               > two_modules[0].params[0].value ? 1 : 0;
     }
     return 1;
}

int main(int argc, char **argv)
{
     CSInitialize(&argc, &argv);
     CSMainLoop(Answer);
     CTerminate();
     return 0;
}
