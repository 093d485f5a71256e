executable: chiba -e light.e chiba.par
communication type: pipes
turtle position: %g %g %g
