# fuzz finding: "every" on a database without states took the last of an empty list
open empty
sequence none.png every 3
