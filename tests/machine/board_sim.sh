# Sourced by the scripts here. start_bench BOARD_SIM SIM_TOML DIR PIERCE_DELAY
# CONFIG: empties DIR, starts kerf-board-sim on a free loopback port (stopped
# when the script exits) and writes DIR/CONFIG: SIM_TOML pointed at that port,
# with this pierce delay. Arguments after CONFIG go to kerf-board-sim.
start_bench() {
  mkdir -p "$3"
  rm -f "$3"/*
  coproc BOARD { exec "$1" --port 0 --watchdog 0.5 "${@:6}"; }
  trap 'kill "$BOARD_PID" 2>/dev/null || true' EXIT
  local line port
  read -r -t 10 line <&"${BOARD[0]}"
  port=${line##*:}
  echo "$line"
  sed -e "s/^port = .*/port = $port/" -e "s/^pierce_delay = .*/pierce_delay = $4/" "$2" >"$3/$5"
}
