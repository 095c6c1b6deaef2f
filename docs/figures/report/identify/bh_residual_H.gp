# B residual against H (structure the J-A set leaves)
# redraw: gnuplot bh_residual_H.gp (in this directory)
set terminal svg noenhanced size 860,440 font 'Helvetica,12' background '#ffffff'
set output 'bh_residual_H.svg'
set grid
set key below horizontal height 1
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 'H [A/m]'
set ylabel 'residual [T]'
plot 'bh.dat' using 2:5 with points pt 7 ps 0.3 lc rgb '#1f77b4' title 'measured - fitted'
unset output
