# B point by point along the loops, measured and fitted
# redraw: gnuplot bh_time.gp (in this directory)
set terminal svg size 860,440 font 'Helvetica,12' background '#ffffff'
set output 'bh_time.svg'
set grid
set key below horizontal noenhanced
set xlabel 'point'
set ylabel 'B [T]'
plot 'bh.dat' using 1:3 with lines lc rgb '#555555' title 'measured', 'bh.dat' using 1:4 with lines lc rgb '#d62728' title 'J-A fit'
unset output
