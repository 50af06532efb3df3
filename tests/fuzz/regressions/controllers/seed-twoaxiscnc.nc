�G91
(ArtCam_Импорт)
XHYH
10 0 0,5

   5	5   
X0Y0
SpEn
SpEn
M03
M05
Out1
Out4
Out1
P0,5
Imp_1_0,001_100
A105
A-0,2455
AH
RunScript_down.script
0,0001 -0,0001 0,0001
1234,5678 0 1