"""A real terminal for tests: a private tmux server, one pane, typed keys."""
import os
import shutil
import subprocess
import tempfile
import time


class Terminal:
    """tmux on its own socket, so it inherits this process's ROS environment
    and never touches the user's tmux; closed (and its server killed) by close()."""

    def __init__(self, command, width=120, height=40, cwd=False):
        self.dir = tempfile.mkdtemp(prefix='turtle_letters_tty_')
        # in a folder of its own, removed by close(): tmux leaves its socket
        # behind, and a server still shutting down refuses a new session of
        # its name ("server exited unexpectedly", seen in a fresh clone's run)
        self.socket = os.path.join(self.dir, 'tmux.socket')
        self._tmux('new-session', '-d', '-x', str(width), '-y', str(height), '-s', 'test',
                   '-c', self.dir if cwd else os.getcwd(), 'bash --norc --noprofile')
        self.tty = self._tmux('display-message', '-p', '-t', 'test', '#{pane_tty}').strip()
        self.send_line(command)

    def _tmux(self, *args):
        return subprocess.run(['tmux', '-S', self.socket, *args], check=True, timeout=10,
                              stdout=subprocess.PIPE, universal_newlines=True).stdout

    def send_line(self, text):
        self._tmux('send-keys', '-t', 'test', '-l', text)
        self._tmux('send-keys', '-t', 'test', 'Enter')

    def send_keys(self, *keys):
        """tmux key names: 'p', 'C-c', 'Enter'..."""
        self._tmux('send-keys', '-t', 'test', *keys)

    def screen(self):
        return self._tmux('capture-pane', '-p', '-t', 'test', '-S', '-200')

    def wait_for(self, text, timeout):
        deadline = time.time() + timeout
        while time.time() < deadline:
            if text in self.screen():
                return True
            time.sleep(0.2)
        return False

    def read(self, name):
        """A file the pane's commands wrote in the terminal's own folder."""
        with open(os.path.join(self.dir, name)) as f:
            return f.read().strip()

    def flags(self):
        return subprocess.run(['stty', '-a', '-F', self.tty], check=True, timeout=10,
                              stdout=subprocess.PIPE, universal_newlines=True).stdout.split()

    def close(self):
        subprocess.run(['tmux', '-S', self.socket, 'kill-server'], timeout=10,
                       stderr=subprocess.DEVNULL)
        shutil.rmtree(self.dir, ignore_errors=True)
