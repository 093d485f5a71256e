executable: honda81 -e branch-tiers.e branch-tiers.par
communication type: pipes
turtle position: %g %g %g
