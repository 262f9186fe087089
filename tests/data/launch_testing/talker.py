"""Prints 'Hello World: N' N times (argv[1]), as demo_nodes' talker logs, then exits with
argv[2] (default 0)."""
import sys
import time

count = int(sys.argv[1])
try:
    for number in range(count):
        print(f'Hello World: {number}', flush=True)
        time.sleep(0.1)
except KeyboardInterrupt:  # stopped by the launch: a clean exit, as a node's
    pass
sys.exit(int(sys.argv[2]) if len(sys.argv) > 2 else 0)
