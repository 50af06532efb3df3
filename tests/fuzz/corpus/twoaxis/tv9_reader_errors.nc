(Errors)
1 2 3 4
(Hello World)
2 0 1,5
M3
G90
1 1
