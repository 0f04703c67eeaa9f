"""Runs a ParaView test command, again (up to 3 times in all) when ParaView aborted because its
render window could not connect to the X server ("bad X server connection"): on a loaded
machine a virtual X server now and then refuses a connection, and VTK's render window aborts
the process instead of retrying (Kerf's own programs retry, see Source/Rendering/KerfDisplay).
Only the last attempt's output is printed, so ctest judges that attempt; any other failure is
final at once.

    RetryLostDisplay.py COMMAND [ARGUMENT...]
"""
import subprocess
import sys
import time

ATTEMPTS = 3
LOST_DISPLAY = "bad X server connection"


def main(command):
    for attempt in range(1, ATTEMPTS + 1):
        run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        output = run.stdout.decode(errors="replace")
        if run.returncode == 0 or LOST_DISPLAY not in output or attempt == ATTEMPTS:
            sys.stdout.write(output)
            return run.returncode
        print("attempt %d of %d: the X server refused ParaView's render window; running again" % (attempt, ATTEMPTS),
              flush=True)
        time.sleep(attempt)
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
