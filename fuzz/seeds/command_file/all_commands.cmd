# every command of docs/post-impact.md "Command files" once (the harness runs them dry)
size 1600 1200
plotsize 1200x800
view iso
view 30 20
up z
mirror xy
fringe vm
range auto
range 0 1e9
bands 12
supersample 2
average off
edges on
legend yes
triad no
units none
scale 2.5
title "a quoted title" # comment
title auto
state middle
state t=5e-6
state -1
mark elem 1 "worst szz"
mark node 2
picture eps_end.png last
mark off
sequence shapes.png 1 6 11
sequence shapes2.png 1:3 5
sequence shapes3.png every 2
sequence shapes4.png count 4
frames anim/vm_ all
history energies.png energy
history elem1.png element 1 eps vm pressure
history node.png node 1 vz disp node 8 ax
history glob.png global ke ie te vx
history mat.png material 1 ie ke hg mass mx vz
echo done
timing on
default
open empty
state first
sequence none.png every 3
picture none.png
