# Sourced by the scripts here. start_bench BOARD_SIM SIM_TOML DIR PIERCE_DELAY
# CONFIG [BOARD_ARGS...]: empties DIR, starts kerf-board-sim on a free loopback port (stopped
# when the script exits) and writes DIR/CONFIG: SIM_TOML pointed at that port,
# with this pierce delay.
start_bench() {
  mkdir -p "$3"
  rm -f "$3"/*
  local board=$1 toml=$2 dir=$3 delay=$4 config=$5
  shift 5
  coproc BOARD { exec "$board" --port 0 --watchdog 0.5 "$@"; }
  trap 'kill "$BOARD_PID" 2>/dev/null || true' EXIT
  local line port
  read -r -t 10 line <&"${BOARD[0]}"
  port=${line##*:}
  echo "$line"
  sed -e "s/^port = .*/port = $port/" -e "s/^pierce_delay = .*/pierce_delay = $delay/" "$toml" >"$dir/$config"
}
