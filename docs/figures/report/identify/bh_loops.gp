# B against H, measured and fitted (improved-pso + Levenberg-Marquardt), fit 97.81 %
# redraw: gnuplot bh_loops.gp (in this directory)
set terminal svg noenhanced size 860,440 font 'Helvetica,12' background '#ffffff'
set output 'bh_loops.svg'
set grid
set key below horizontal height 1
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 'H [A/m]'
set ylabel 'B [T]'
plot 'bh.dat' using 2:4 with lines lw 2 lc rgb '#d62728' title 'J-A fit', \
     '' using 2:3 with points pt 7 ps 0.5 lc rgb '#888888' title 'measured'
unset output
