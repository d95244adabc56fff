set terminal pngcairo size 900,600 font ',10'
set output 'doc/work_precision/contact_precision.png'
set datafile separator ','
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'run time of the four scenes [s]'
set ylabel 'largest error after 0.5 s'
set grid
set title 'sustained contact: error against run time (labels: contact\_tolerance)'
set key top right
plot 'doc/work_precision/contact_precision.csv' using 2:3 skip 1 with linespoints pointsize 1.5 title 'position [m]', '' using 2:4 skip 1 with linespoints pointsize 1.5 title 'velocity [m/s]', '' using 2:3:1 skip 1 with labels offset 0,1 notitle
