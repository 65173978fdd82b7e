light 0 0 10 1 1 1
push scale 0.9 0.9 0.9 rotate 0 0 1 10 sphere 1 0 0 0.3
push scale 0.9 6.9 0.9 rotate 0 0 1 10 sphere 1 0 0 0.3
push scale 0.9 0.91e-300 0.9 rotate 0 0 1 10 sphere 1 0 0 0.3
push scale 0.9 0.9 0.9 rotate 0 0 1 10 sphere 1 0 0 0.3
push scale 0.9 0.9 0.9 rotate 0 0 1 10 sphere 1 0 0 0.3
push scale 4.9 1.1 0.9 rotate 0 1 1 10 sphere 0 0 0 0.3 cone 0 0 0 1 0 0 1 0
push scale 0.9 0.9 0.9 rotate 0 0 1 10 sphere 1 0 0 0.3
push scale 0.9 0.9 0.9 rotate 0 0 1 10 sphere 1 0 0 0.3
pop pop pop pop pop pop pop pop
push push push pop pop pop
