# best fitness of the global search against model evaluations
# redraw: gnuplot convergence.gp (in this directory)
set terminal svg noenhanced size 860,440 font 'Helvetica,12' background '#ffffff'
set output 'convergence.svg'
set grid
set key below horizontal height 1
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 'evaluations'
set ylabel 'best fitness [T]'
set logscale y
plot 'convergence.dat' using 1:3 with steps lw 1 lc rgb '#9ecae1' title 'best of the search box in use', \
     '' using 1:2 with steps lw 2 lc rgb '#1f77b4' title 'global best'
unset output
