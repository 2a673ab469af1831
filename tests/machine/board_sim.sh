# Sourced by the scripts here: start_board BOARD_SIM starts kerf-board-sim on
# a free loopback port, sets $port, and stops the board when the script exits.
start_board() {
  coproc BOARD { exec "$1" --port 0 --watchdog 0.5; }
  trap 'kill "$BOARD_PID" 2>/dev/null || true' EXIT
  local line
  read -r -t 10 line <&"${BOARD[0]}"
  port=${line##*:}
  echo "$line"
}
