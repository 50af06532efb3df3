# The starter posts `postproc new-post --template NAME` writes: NAME|sample job|controllers it is for.
# Each is a post we ship and test, machines/NAME/NAME.gpp with its machine file NAME.prp; the sample
# job (docs/examples/JOB.trace) is the one its golden tests post.
set(POST_TEMPLATES
  "fanuc|sample-job|Fanuc 0i/31i-M and Fanuc-family mills (Haas, Brother, ...): M98/M99 subprograms, G81-G89 cycles"
  "linuxcnc|sample-job|LinuxCNC 2.8+ and Mach3/Mach4: M98/M99 subprograms, G81-G89 cycles, o-word repeat loops"
  "grbl|planes-helix|GRBL 1.1 routers and hobby mills: no cycles, subprograms or cutter compensation on the control"
  "sinumerik|sample-job|Siemens Sinumerik 828D/840D sl mills: CYCLE81-CYCLE89, subprograms in .SPF files"
  "fanuc-lathe|turning-job|Fanuc 0i-TF/31i-T lathes: G71/G70 P Q, G75, G76, G96/G50, X as a diameter"
  "mill-turn|mill-turn-job|lathes with live tools, C and Y axes (Integrex style): turning, C-axis drilling, G12.1"
  "wire-edm|wire-edm-job|Fanuc/Sodick-style wire EDM: passes by M98 with E/D, G92 start, G51/G52 tapers, U/V"
)
