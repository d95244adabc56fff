set terminal pngcairo size 900,600 font ',10'
set output 'doc/work_precision/ball_impact.png'
set datafile separator ','
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'run time per impact [s]'
set ylabel 'largest error per unit speed'
set grid
set title 'mathavan2014 ball-ball impact: error against run time (labels: tolerance)'
set key top right
plot 'doc/work_precision/ball_impact.csv' using 2:3 skip 1 with linespoints pointsize 1.5 title 'velocity', '' using 2:4 skip 1 with linespoints pointsize 1.5 title 'R x spin', '' using 2:3:1 skip 1 with labels offset 0,1 notitle
