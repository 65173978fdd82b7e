include self.sc
include ab.sc
include broken.sc
include folder
include missing.sc
include "unterminated.sc
include ""
include
