"""Keys as characters: arrows are chr(18..21) (left, up, right, down), as SOFA's viewers send them."""
import string as _string

leftarrow = chr(18)
uparrow = chr(19)
rightarrow = chr(20)
downarrow = chr(21)
space = " "
plus = "+"
minus = "-"
for _i in range(10):
    globals()["KP_%d" % _i] = str(_i)
for _c in _string.ascii_uppercase:
    globals()[_c] = _c
del _i, _c, _string
