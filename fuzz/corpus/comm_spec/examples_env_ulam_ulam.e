executable: density ulam.par
communication type: pipes
turtle position: %g %g %g
