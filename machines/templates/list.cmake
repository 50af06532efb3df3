# The starter posts `postproc new-post --template NAME` writes: NAME|controllers it is for.
# Each is a post we ship and test, machines/NAME/NAME.gpp with its machine file NAME.prp.
set(POST_TEMPLATES
  "fanuc|Fanuc 0i/31i-M and Fanuc-family mills (Haas, Brother, ...): M98/M99 subprograms, G81-G89 cycles"
  "linuxcnc|LinuxCNC 2.8+ and Mach3/Mach4: M98/M99 subprograms, G81-G89 cycles, o-word repeat loops"
  "grbl|GRBL 1.1 routers and hobby mills: no cycles, subprograms or cutter compensation on the control"
  "sinumerik|Siemens Sinumerik 828D/840D sl mills: CYCLE81-CYCLE89, subprograms in .SPF files"
)
