#!/usr/bin/env bash
# Explores one world twice with the same method, seed and options: in-process
# (`roomscout explore`, growing map) and over ROS (roomscout_sim_node + roomscout_explore_node
# on a private rosmaster), and prints T98 and L98 of both, and the wall time of the ROS run.
# Usage: scripts/ros_vs_inprocess.sh [world] [method] [seed] [build-dir]
set -euo pipefail
world="${1:-small_house}"; method="${2:-semantic}"; seed="${3:-1}"
build="$(cd "${4:-build}" && pwd)"
bin="$build/ros_package/roomscout/bin"
work="$(mktemp -d)"
pids=()
cleanup() { for p in "${pids[@]}"; do kill -INT "$p" 2>/dev/null || true; done; sleep 1
            for p in "${pids[@]}"; do kill -KILL "$p" 2>/dev/null || true; done; rm -rf "$work"; }
trap cleanup EXIT

# The simulator's stall threshold (0.1 % of the reachable floor) needs the world's truth,
# which the explore node lacks: take it from an in-process run and give it to both.
"$build/roomscout" explore --world "$world" --method "$method" --seed "$seed" --max-time 1 --out "$work/probe" >/dev/null
stall=$(/usr/bin/python3 -c "import json,sys; print(0.001*json.load(open(sys.argv[1]))['reachable_area_m2'])" "$work/probe/metrics.json")
printf 'episode:\n  map_mode: growing\n  stall_min_new_area_m2: %s\n' "$stall" > "$work/options.yaml"

"$build/roomscout" explore --world "$world" --method "$method" --seed "$seed" --config "$work/options.yaml" \
  --out "$work/inprocess" >/dev/null
/usr/bin/python3 - "$work/inprocess/metrics.json" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
print(f"in-process: rate {m['exploration_rate']:.4f}  T98 {m['t98_s']:.1f} s  L98 {m['l98_m']:.1f} m"
      f"  goals {m['goals']}  failed {m['goal_failures']}")
PY

port=$(/usr/bin/python3 -c "import socket; s=socket.socket(); s.bind(('127.0.0.1',0)); print(s.getsockname()[1])")
export ROS_MASTER_URI="http://localhost:$port" ROS_HOSTNAME=localhost ROS_HOME="$work/ros" ROS_LOG_DIR="$work/ros/log"
/usr/bin/python3 /usr/bin/rosmaster --core -p "$port" >"$work/master.log" 2>&1 & pids+=($!)
for _ in $(seq 100); do (echo > /dev/tcp/127.0.0.1/$port) 2>/dev/null && break; sleep 0.1; done
/usr/bin/python3 /usr/bin/rosparam set /use_sim_time true
start=$(date +%s.%N)
"$bin/roomscout_sim_node" __name:=sim _world:="$world" _seed:="$seed" _config:="$work/options.yaml" _sync_topic:=/explore/cycle _sync_timeout_s:=0 >"$work/sim.log" 2>&1 & pids+=($!)
"$bin/roomscout_explore_node" __name:=explore _method:="$method" _seed:="$seed" _config:="$work/options.yaml" \
  _save_dir:="$work/ros_maps" >"$work/explore.log" 2>&1 & pids+=($!)
until /usr/bin/python3 /usr/bin/rostopic echo -n1 /explore/status 2>/dev/null | grep -q '\\"done\\": true\|\\"done\\":true'; do
  kill -0 "${pids[1]}" "${pids[2]}" 2>/dev/null || { echo "a node exited early"; tail "$work"/*.log; exit 1; }
  sleep 1
done
end=$(date +%s.%N)
explored=$(/usr/bin/python3 /usr/bin/rostopic echo -n1 /explore/status | /usr/bin/python3 -c "
import json, sys, yaml
s = json.loads(yaml.safe_load(sys.stdin.read().split('---')[0])['data'])
print(f\"goals {s['goals']}  failed {s['goal_failures']}  cycles {s['cycles']}\")")
/usr/bin/python3 /usr/bin/rostopic echo -n1 /sim/status | /usr/bin/python3 -c "
import json, sys, yaml
s = json.loads(yaml.safe_load(sys.stdin.read().split('---')[0])['data'])
print(f\"over ROS:   rate {s['rate']:.4f}  T98 {s['t98_s']:.1f} s  L98 {s['l98_m']:.1f} m  $explored  wall $(echo "$end - $start" | bc) s\")"
[ -z "${KEEP_LOGS:-}" ] || cp "$work"/*.log "$KEEP_LOGS"/
