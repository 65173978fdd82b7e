# The sandbox holds part.sc, glass.sc, self.sc (includes itself), ab.sc and
# ba.sc (include each other), broken.sc (errors) and the directory folder.
light 0 5 5 1 1 1
include part.sc
push
translate 2 0 0
include "glass.sc"
pop
include glass.sc
