#!/usr/bin/env bash
# What the camera's 1920x1200 images cost the table node, by where their subscriber is: none; a
# subscriber in another process (over TCP: table_node and `nodelet standalone cue_sim/ImageRate`);
# and one in the same nodelet manager (cue_sim/TableNodelet and cue_sim/ImageRate: each image
# handed over as a shared pointer). For each, the node's CPU over SECONDS (its process's user and
# system time; in the manager the consumer's share is a counter increment a frame), and the
# frames the subscriber got.
#   scripts/camera_cpu.sh [SECONDS]      (default 20)
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
source "$here/env.sh"
cue_sim_source_devel
seconds="${1:-20}"
cue_sim_private_master 11911 camera_cpu
log="$ROS_LOG_DIR/camera_cpu"
mkdir -p "$log"
ticks=$(getconf CLK_TCK)

# The process's user + system CPU time in clock ticks.
cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }

# Waits until the process's log says the consumer gets images (its first report), or 60 s.
wait_for_images() {
  for _ in $(seq 300); do
    grep -q 'image_rate: [1-9][0-9]* frames' "$1" 2>/dev/null && return 0
    sleep 0.2
  done
  echo "camera_cpu: no images reached the consumer (see $1)" >&2
  return 1
}

# CPU share of a core [%] the process $1 took over $seconds.
measure() {
  local pid=$1 before after
  before=$(cpu_ticks "$pid")
  sleep "$seconds"
  after=$(cpu_ticks "$pid")
  awk -v t=$((after - before)) -v hz="$ticks" -v s="$seconds" 'BEGIN { printf "%.1f", 100 * t / hz / s }'
}

# The consumer's mean rate over its reports during the measurement.
rate_of() { grep -o 'image_rate: [0-9]* frames in [0-9.]* s: [0-9.]* Hz' "$1" | tail -n +2 | awk '{ s += $7; n++ } END { if (n) printf "%.1f", s / n; else print "-" }'; }

stop() { kill "$@" 2>/dev/null || true; wait "$@" 2>/dev/null || true; }

params() {
  rosparam load "$CUE_SIM_ROOT/config/physics.yaml" /table
  rosparam load "$CUE_SIM_ROOT/config/table_node.yaml" /table
  rosparam set /table/aim_marker false
}
params
printf '| subscriber to ~camera/image_raw (1920x1200, 30 Hz) | node CPU [%% of a core] | frames received [Hz] |\n|---|---|---|\n'

# 1. No subscriber: the node alone.
"$CUE_SIM_DEVEL/lib/cue_sim/table_node" __name:=table > "$log/alone.log" 2>&1 &
node=$!
cue_sim_pids+=("$node")
for _ in $(seq 100); do rosservice list 2>/dev/null | grep -q '^/table/strike$' && break; sleep 0.2; done
printf '| none | %s | - |\n' "$(measure "$node")"

# 2. Over TCP: ImageRate in its own process.
/usr/lib/nodelet/nodelet standalone cue_sim/ImageRate __name:=image_rate image:=/table/camera/image_raw \
  _report_period:=2.0 > "$log/tcp_consumer.log" 2>&1 &
consumer=$!
cue_sim_pids+=("$consumer")
wait_for_images "$log/tcp_consumer.log"
cpu=$(measure "$node")
printf '| another process (TCP) | %s | %s |\n' "$cpu" "$(rate_of "$log/tcp_consumer.log")"
stop "$consumer" "$node"

# 3. In the same manager: the table and ImageRate as nodelets.
/usr/lib/nodelet/nodelet manager __name:=table_manager > "$log/manager.log" 2>&1 &
manager=$!
cue_sim_pids+=("$manager")
/usr/lib/nodelet/nodelet load cue_sim/TableNodelet table_manager __name:=table > "$log/table_loader.log" 2>&1 &
cue_sim_pids+=($!)
for _ in $(seq 100); do rosservice list 2>/dev/null | grep -q '^/table/strike$' && break; sleep 0.2; done
/usr/lib/nodelet/nodelet load cue_sim/ImageRate table_manager __name:=image_rate image:=/table/camera/image_raw \
  _report_period:=2.0 > "$log/consumer_loader.log" 2>&1 &
cue_sim_pids+=($!)
wait_for_images "$log/manager.log"
cpu=$(measure "$manager")
printf '| the same nodelet manager (shared pointer) | %s | %s |\n' "$cpu" "$(rate_of "$log/manager.log")"
