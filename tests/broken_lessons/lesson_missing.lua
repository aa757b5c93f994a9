-- expect: 1: the script never says what it is; begin it with lesson{
ground { material = "wood" }
