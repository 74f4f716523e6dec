# Sourced by the paint tests: sets $python to an interpreter with numpy, or skips the test (77).
python=""
for candidate in python3 /usr/bin/python3; do
  if "$candidate" -c "import numpy" 2>/dev/null; then python=$candidate; break; fi
done
[ -n "$python" ] || { echo "skipped: no Python with numpy (Debian: apt-get install python3-numpy)"; exit 77; }
