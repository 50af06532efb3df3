10 0 0,5
RunScript_down.script
RunScript_loop.script
RunScript_missing.script
5 5
