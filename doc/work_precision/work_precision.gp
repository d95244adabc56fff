set terminal pngcairo size 1500,900 font ',10'
set output 'doc/work_precision/work_precision.png'
set datafile separator ','
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'run time per shot [s]'
set ylabel 'largest position error [m]'
set grid
set key top right noenhanced
set yrange [1e-17:1e3]
set offsets graph 0.04, graph 0.04, 0, 0
set multiplot layout 2,3 title 'cue\_sim: error against run time (reference: long-double event engine)'
set title 'single ball sliding to rest' noenhanced
plot for [m in 'event symplectic_euler rk4 dopri54'] 'doc/work_precision/results.csv' using (strcol(1) eq 'single ball sliding to rest' && strcol(2) eq m ? $4 : 1/0):($5 > 0 ? $5 : 1e-17) with linespoints pointsize 1.5 title m
set title 'stun cut shot' noenhanced
plot for [m in 'event symplectic_euler rk4 dopri54'] 'doc/work_precision/results.csv' using (strcol(1) eq 'stun cut shot' && strcol(2) eq m ? $4 : 1/0):($5 > 0 ? $5 : 1e-17) with linespoints pointsize 1.5 title m
set title 'draw shot off a cushion' noenhanced
plot for [m in 'event symplectic_euler rk4 dopri54'] 'doc/work_precision/results.csv' using (strcol(1) eq 'draw shot off a cushion' && strcol(2) eq m ? $4 : 1/0):($5 > 0 ? $5 : 1e-17) with linespoints pointsize 1.5 title m
set title 'jump shot with draw over a ball' noenhanced
plot for [m in 'event symplectic_euler rk4 dopri54'] 'doc/work_precision/results.csv' using (strcol(1) eq 'jump shot with draw over a ball' && strcol(2) eq m ? $4 : 1/0):($5 > 0 ? $5 : 1e-17) with linespoints pointsize 1.5 title m
set title '9-ball break' noenhanced
plot for [m in 'event symplectic_euler rk4 dopri54'] 'doc/work_precision/results.csv' using (strcol(1) eq '9-ball break' && strcol(2) eq m ? $4 : 1/0):($5 > 0 ? $5 : 1e-17) with linespoints pointsize 1.5 title m
set title '8-ball break' noenhanced
plot for [m in 'event symplectic_euler rk4 dopri54'] 'doc/work_precision/results.csv' using (strcol(1) eq '8-ball break' && strcol(2) eq m ? $4 : 1/0):($5 > 0 ? $5 : 1e-17) with linespoints pointsize 1.5 title m
unset multiplot
