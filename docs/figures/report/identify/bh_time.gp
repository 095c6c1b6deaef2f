# B point by point along the loops, measured and fitted
# redraw: gnuplot bh_time.gp (in this directory)
set terminal svg noenhanced size 860,440 font 'Helvetica,12' background '#ffffff'
set output 'bh_time.svg'
set grid
set key below horizontal height 1
set offsets 0, 0, graph 0.05, graph 0.05
set xlabel 'point'
set ylabel 'B [T]'
plot 'bh.dat' using 1:4 with lines lw 1 lc rgb '#d62728' title 'J-A fit', \
     '' using 1:3 with lines lw 1 lc rgb '#555555' title 'measured'
unset output
