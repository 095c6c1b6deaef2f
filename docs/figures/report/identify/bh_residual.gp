# B residual, measured - fitted, point by point
# redraw: gnuplot bh_residual.gp (in this directory)
set terminal svg size 860,440 font 'Helvetica,12' background '#ffffff'
set output 'bh_residual.svg'
set grid
set key below horizontal noenhanced
set xlabel 'point'
set ylabel 'residual [T]'
plot 'bh.dat' using 1:5 with lines lc rgb '#1f77b4' title 'measured - fitted'
unset output
