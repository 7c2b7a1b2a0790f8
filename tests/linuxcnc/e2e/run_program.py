#!/usr/bin/python3
"""A display for LinuxCNC that shows nothing: switches the machine on, homes it, runs one
program and quits (linuxcnc_e2e.sh). KIN5_E2E_PROGRAM names the program; the outcome, "ok" or
what went wrong, is written to KIN5_E2E_STATUS."""
import os
import sys
import time

import linuxcnc

program = os.environ["KIN5_E2E_PROGRAM"]
status_file = os.environ["KIN5_E2E_STATUS"]
command, stat, errors = linuxcnc.command(), linuxcnc.stat(), linuxcnc.error_channel()


def finish(message, code):
    with open(status_file, "w") as f:
        f.write(message + "\n")
    sys.exit(code)


def wait(condition, what, timeout_s=60.0):
    end = time.time() + timeout_s
    while time.time() < end:
        stat.poll()
        error = errors.poll()
        if error:
            finish("LinuxCNC error while %s: %s" % (what, error[1]), 1)
        if condition():
            return
        time.sleep(0.01)
    finish("timed out " + what, 1)


wait(lambda: True, "starting")
command.state(linuxcnc.STATE_ESTOP_RESET)
command.wait_complete()
command.state(linuxcnc.STATE_ON)
command.wait_complete()
wait(lambda: stat.task_state == linuxcnc.STATE_ON, "switching on")
command.mode(linuxcnc.MODE_MANUAL)
command.wait_complete()
command.home(-1)
command.wait_complete()
wait(lambda: all(stat.homed[j] for j in range(stat.joints)), "homing")
command.mode(linuxcnc.MODE_AUTO)
command.wait_complete()
command.program_open(program)
command.wait_complete()
command.auto(linuxcnc.AUTO_RUN, 0)
wait(lambda: stat.interp_state != linuxcnc.INTERP_IDLE, "starting the program", 10.0)
wait(lambda: stat.interp_state == linuxcnc.INTERP_IDLE and stat.queue == 0, "running the program", 100.0)
time.sleep(0.3)  # a few hundred servo cycles at rest after the last move
finish("ok", 0)
