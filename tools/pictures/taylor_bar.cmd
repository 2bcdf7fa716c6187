# README pictures of the Taylor bar (seed example 1, paper fig. 9-11).
# Run in the run folder (out/seed/taylor_bar/), e.g. by tools/make-readme-pictures.sh:
#   postimpact d3plot -d DIR -c tools/pictures/taylor_bar.cmd
# Quarter model: mirrored across x = 0 and y = 0 to the whole bar.
size 1000 750
plotsize 1000 625
fringe eps
# fixed range: the largest strains (up to ~3.2) lie in the thin flattened layer at the impact
# face; above 1.6 is drawn red, the legend gives the true maximum
range 0 1.6
bands 8

# fig. 9: successive deformed shapes, every 20 us, seen from the side
mirror xy
view -90 20
size 1000 650
sequence taylor_bar_shapes.png 1 6 11 16 21
size 1000 750

# fig. 11: the deformed bar at 80 us in perspective (axonometric)
view -60 30
picture taylor_bar_final.png last

# half bar (mirrored across x = 0 only): the symmetry plane y = 0 shows the plastic zone inside
mirror x
view -75 15
picture taylor_bar_section.png last

# fig. 10: time histories from the time-history database (every 1 us)
open d3thdt
title Taylor bar: impact-end axis node 1 and top axis node 1333
history taylor_bar_nodes.png node 1 vz dz node 1333 vz dz
title Taylor bar: element 1 (impact-end element on the axis)
history taylor_bar_element1.png element 1 eps szz sxx vm pressure
title Taylor bar (quarter model): energies
plotsize 1000 750
history taylor_bar_energies.png energy
