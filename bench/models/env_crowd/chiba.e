executable: chiba chiba.par
communication type: pipes
turtle position: %g %g %g
