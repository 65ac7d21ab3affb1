# Option parsing shared by the launch scripts (sourced: . "$(dirname "$0")/lib/options.sh").

# need_value OPTION [VALUE ...]: one line naming the option, and exit status 2, where no value follows it.
need_value() { [ $# -ge 2 ] && [ -n "$2" ] || { echo "launch/${0##*/}: $1 needs a value (see launch/${0##*/} --help)" >&2; exit 2; }; }
