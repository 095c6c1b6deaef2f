# autocorrelation of the B residual, 95 % bounds +-0.0863
# redraw: gnuplot residual_autocorrelation.gp (in this directory)
set terminal svg noenhanced size 860,440 font 'Helvetica,12' background '#ffffff'
set output 'residual_autocorrelation.svg'
set grid
set key below horizontal height 1
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 'lag [points]'
set ylabel 'autocorrelation [-]'
set yrange [-1:1]
plot 'autocorrelation.dat' using 1:2 with impulses lw 2 lc rgb '#1f77b4' title 'r(k)', \
     '' using 1:3 with lines lw 1 dt 2 lc rgb '#d62728' title '95 % bound', \
     '' using 1:4 with lines lw 1 dt 2 lc rgb '#d62728' notitle
unset output
