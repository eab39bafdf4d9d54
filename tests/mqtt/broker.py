# SPDX-License-Identifier: BSD-2-Clause
"""A real mosquitto broker on 127.0.0.1 for the tests: a free port, a temporary folder for
its configuration, log and persistence file, and stop()/start() to take it away and bring it
back on the same port (docs/mqtt.md, "The fault test")."""
import getpass
import os
import shutil
import socket
import subprocess
import time


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def port_open(port):
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=0.2):
            return True
    except OSError:
        return False


class Broker:
    def __init__(self, folder):
        self.folder = folder
        self.port = free_port()
        self.proc = None
        self.restarts = 0
        self.config = os.path.join(folder, "mosquitto.conf")
        with open(self.config, "w") as f:
            f.write("listener %d 127.0.0.1\n" % self.port)
            f.write("allow_anonymous true\n")
            # The subscriber's session and its queued messages survive a restart: the
            # broker writes them to mosquitto.db when it stops on SIGTERM.
            f.write("persistence true\n")
            f.write("persistence_location %s/\n" % folder)
            f.write("max_queued_messages 0\n")  # no limit on a session's queue
            f.write("log_dest file %s/mosquitto.log\n" % folder)
            # As root mosquitto would switch to the user `mosquitto`, who cannot write here.
            f.write("user %s\n" % getpass.getuser())

    @staticmethod
    def program():
        return shutil.which("mosquitto") or ("/usr/sbin/mosquitto" if os.path.exists("/usr/sbin/mosquitto") else None)

    def start(self, timeout=10):
        self.proc = subprocess.Popen([self.program(), "-c", self.config],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        deadline = time.monotonic() + timeout
        while not port_open(self.port):
            if self.proc.poll() is not None:
                raise RuntimeError("mosquitto exited with status %d (log: %s/mosquitto.log)"
                                   % (self.proc.returncode, self.folder))
            if time.monotonic() > deadline:
                raise RuntimeError("mosquitto did not listen on 127.0.0.1:%d within %d s" % (self.port, timeout))
            time.sleep(0.05)

    def stop(self, timeout=10):
        """SIGTERM: the broker saves its persistence file and exits."""
        if self.proc and self.proc.poll() is None:
            self.proc.terminate()
            self.proc.wait(timeout=timeout)
        self.proc = None

    def restart(self, pause):
        self.stop()
        time.sleep(pause)
        self.start()
        self.restarts += 1

    def url(self, topic):
        return "mqtt://127.0.0.1:%d/%s" % (self.port, topic)
