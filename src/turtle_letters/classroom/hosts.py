"""Whether the host name this machine advertises will do: check_network.py's
verdict, from what the name resolves to and the machine's own addresses.
No ROS, no network."""


def host_verdict(host, source, addresses, local_addresses, others_must_reach):
    """(passed, line) for the advertised host name, from what it resolves
    to (`addresses`) and this machine's own addresses. No ROS, no network."""
    if not addresses:
        return False, (f'this machine advertises itself as {host!r} ({source}), which does not '
                       'resolve here: set ROS_IP to one of its addresses')
    loopback = all(a.startswith('127.') or a == '::1' for a in addresses)
    if loopback and others_must_reach:
        return False, (f'this machine advertises itself as {host!r} ({source}) = '
                       f'{", ".join(addresses)}, which other machines cannot reach: set ROS_IP '
                       f'to its address on the network they share ({", ".join(_reachable(local_addresses)) or "none found"})')
    own = [a for a in addresses if a in local_addresses]
    if not own:
        return False, (f'this machine advertises itself as {host!r} ({source}), which resolves to '
                       f'{", ".join(addresses)}, not to any of its own addresses '
                       f'({", ".join(local_addresses)}): fix ROS_HOSTNAME or /etc/hosts, or set ROS_IP')
    if loopback:
        return True, (f'this machine advertises itself as {host!r} ({source}) = '
                      f'{", ".join(own)}: nodes on this machine only')
    return True, (f'this machine advertises itself as {host!r} ({source}) = {", ".join(own)}, '
                  'one of its own addresses; the other machines must resolve and reach it too')


def _reachable(addresses):
    return [a for a in addresses if not a.startswith('127.') and a != '::1']
