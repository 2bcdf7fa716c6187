# README pictures of the crossed half-cylinders (seed example 3, paper fig. 15-17).
# Run in the run folder (out/seed/crossed_cylinders/), e.g. by tools/make-readme-pictures.sh:
#   postimpact d3plot -d DIR -c tools/pictures/crossed_cylinders.cmd
# Quarter model (x >= 0, y >= 0): mirrored across x = 0 and y = 0 to the two whole bodies.
size 1000 750
plotsize 1000 625
mirror xy
view 30 25

# fig. 15: initial geometry and mesh, a colour per body
fringe material
picture crossed_cylinders_initial.png first

# fig. 17: final state (50 us, bodies separated) with the effective plastic strain
fringe eps
picture crossed_cylinders_final.png last

# half model (mirrored across x = 0 only): the plane y = 0 cuts body 1 along its axis and
# body 2 across it, through the contact point (element 1 = the seed's point 1)
mirror x
view -60 20
picture crossed_cylinders_section.png last

# fig. 16: stresses and plastic strain at point 1 (element 1), every 0.2 us; energies (the
# two bodies are alike: the totals and the hourglass energy of each body)
open d3thdt
title Crossed half-cylinders: point 1 (element 1, body 1 at the contact point)
history crossed_cylinders_element1.png element 1 eps szz sxx syy vm pressure
title Crossed half-cylinders (quarter model): energies
plotsize 1000 750
history crossed_cylinders_energies.png global ke ie te material 1 hg material 2 hg
