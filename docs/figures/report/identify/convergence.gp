# best fitness of the global search against model evaluations
# redraw: gnuplot convergence.gp (in this directory)
set terminal svg size 860,440 font 'Helvetica,12' background '#ffffff'
set output 'convergence.svg'
set grid
set key below horizontal noenhanced
set xlabel 'evaluations'
set ylabel 'best fitness [T]'
set logscale y
plot 'convergence.dat' using 1:2 with steps lw 2 title 'global best'
unset output
