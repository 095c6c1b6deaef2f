# B residual, measured - fitted, point by point
# redraw: gnuplot bh_residual.gp (in this directory)
set terminal svg noenhanced size 860,440 font 'Helvetica,12' background '#ffffff'
set output 'bh_residual.svg'
set grid
set key below horizontal height 1
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 'point'
set ylabel 'residual [T]'
plot 'bh.dat' using 1:5 with lines lw 1 lc rgb '#1f77b4' title 'measured - fitted'
unset output
