"""Machines made of Linux network namespaces on one host, joined by a
bridge, each with its own /etc/hosts (/etc/netns/NS/hosts), ROS_MASTER_URI
and ROS_HOSTNAME; and what the network tests do on them.

Addresses are from TEST-NET-2 (198.51.100.0/24, RFC 5737), and live only in
the namespaces made here, which `classroom` removes at the end whatever
happens. Needs root (CI runs as root); elsewhere the tests are skipped,
saying why.
"""
import contextlib
import csv
import os
import re
import shutil
import signal
import subprocess
import tempfile
import time

import pytest

from support.children import readable_env

SUBNET = '198.51.100'


def run(*command):
    subprocess.run(command, check=True, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                   universal_newlines=True)


class Network:
    """The namespaces, the bridge between them, and their hosts files.
    `addresses`: {host: last byte of its address}; `unknown`: pairs (a, b)
    where host a cannot resolve host b."""

    def __init__(self, addresses, unknown=()):
        tag = f'tl{os.getpid() % 100000}'
        self.addresses = addresses
        self.unknown = set(unknown)
        self.switch = f'{tag}-switch'
        self.ns = {host: f'{tag}-{host}' for host in addresses}
        self.made = []

    def make(self):
        for ns in [self.switch, *self.ns.values()]:
            run('ip', 'netns', 'add', ns)
            self.made.append(ns)
        run('ip', '-n', self.switch, 'link', 'add', 'br0', 'type', 'bridge')
        run('ip', '-n', self.switch, 'link', 'set', 'br0', 'up')
        for host, number in self.addresses.items():
            ns, port = self.ns[host], f'port{number}'
            # Made inside the switch's namespace, one end moved straight into
            # the host's: nothing of it is ever in this machine's own.
            run('ip', '-n', self.switch, 'link', 'add', port, 'type', 'veth',
                'peer', 'name', 'eth0', 'netns', ns)
            run('ip', '-n', self.switch, 'link', 'set', port, 'master', 'br0')
            run('ip', '-n', self.switch, 'link', 'set', port, 'up')
            run('ip', '-n', ns, 'addr', 'add', f'{SUBNET}.{number}/24', 'dev', 'eth0')
            run('ip', '-n', ns, 'link', 'set', 'eth0', 'up')
            run('ip', '-n', ns, 'link', 'set', 'lo', 'up')
            known = [h for h in self.addresses if (host, h) not in self.unknown]
            os.makedirs(f'/etc/netns/{ns}', exist_ok=True)
            with open(f'/etc/netns/{ns}/hosts', 'w') as f:
                f.write('127.0.0.1 localhost\n')
                f.writelines(f'{SUBNET}.{self.addresses[h]} {h}\n' for h in known)

    def link(self, host, up):
        """Pull the host's cable out (up=False), or put it back."""
        run('ip', '-n', self.ns[host], 'link', 'set', 'eth0', 'up' if up else 'down')

    def remove(self):
        for ns in reversed(self.made):
            pids = subprocess.run(['ip', 'netns', 'pids', ns], stdout=subprocess.PIPE,
                                  universal_newlines=True).stdout.split()
            for pid in pids:
                try:
                    os.kill(int(pid), signal.SIGKILL)
                except (ProcessLookupError, ValueError):
                    pass
            subprocess.run(['ip', 'netns', 'del', ns])
            shutil.rmtree(f'/etc/netns/{ns}', ignore_errors=True)


class Host:
    """Commands run on one of the machines, as its user would run them."""

    def __init__(self, network, name, home):
        self.network = network
        self.ns = network.ns[name]
        self.name = name
        self.home = os.path.join(home, name)
        os.makedirs(self.home)
        self.env = readable_env({k: v for k, v in os.environ.items()
                                 if k not in ('ROS_IP', 'ROS_HOSTNAME')})
        self.env.update(ROS_MASTER_URI='http://master:11311', ROS_HOSTNAME=name,
                        ROS_HOME=self.home, QT_QPA_PLATFORM='offscreen')
        self.env.pop('DISPLAY', None)
        self.processes = []

    def start(self, label, *command):
        out = open(os.path.join(self.home, f'{label}.out'), 'w')
        process = subprocess.Popen(['ip', 'netns', 'exec', self.ns, *command], env=self.env,
                                   stdout=out, stderr=subprocess.STDOUT,
                                   stdin=subprocess.DEVNULL, start_new_session=True)
        process.out_path = out.name
        self.processes.append(process)
        return process

    def call(self, *command, timeout=60):
        return subprocess.run(['ip', 'netns', 'exec', self.ns, *command], env=self.env,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              universal_newlines=True, timeout=timeout)

    def stop_all(self):
        for process in self.processes:
            stop(process)


def stop(process, timeout=20):
    """Ctrl-C, as a user would; returns how long it took to end (None: it had to be killed)."""
    if process.poll() is not None:
        return 0.0
    started = time.time()
    os.killpg(process.pid, signal.SIGINT)
    try:
        process.wait(timeout)
        return time.time() - started
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.wait()
        return None


def output(process):
    with open(process.out_path) as f:
        return f.read()


def wait_for_line(process, pattern, timeout):
    deadline = time.time() + timeout
    while time.time() < deadline:
        match = re.search(pattern, output(process))
        if match:
            return match
        if process.poll() is not None:
            break
        time.sleep(0.1)
    pytest.fail(f'no line matching {pattern!r} within {timeout} s; the output ends:\n'
                f'{output(process)[-3000:]}')


def log_time(process, text):
    """The time stamp of the first rospy log line containing `text`."""
    match = re.search(r'\[(?:INFO|WARN|ERROR)\] \[(\d+\.\d+)\]: [^\n]*' + re.escape(text),
                      output(process))
    return float(match.group(1)) if match else None


def read_poses(path):
    """rostopic echo -p output: (x, y, theta) rows."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [(float(r['field.x']), float(r['field.y']), float(r['field.theta'])) for r in rows]


@contextlib.contextmanager
def classroom(addresses, unknown=()):
    """{host: Host} on a network of their own, removed afterwards."""
    if os.geteuid() != 0:
        pytest.skip('network namespaces need root (CI runs as root): not run')
    if shutil.which('ip') is None:
        pytest.skip("network namespaces need the ip command (iproute2), which is missing")
    network = Network(addresses, unknown)
    home = tempfile.mkdtemp(prefix='turtle_letters_network_')
    hosts = {}
    try:
        try:
            network.make()
        except subprocess.CalledProcessError as e:
            pytest.skip(f'could not make network namespaces here: {e.output.strip()}')
        hosts = {name: Host(network, name, home) for name in addresses}
        yield hosts
    except BaseException as e:
        if not isinstance(e, pytest.skip.Exception):
            print(f'\nlogs of the run: {home}')     # kept where the test failed
            home = None
        raise
    finally:
        for host in hosts.values():
            host.stop_all()
        network.remove()
        if home:
            shutil.rmtree(home, ignore_errors=True)
