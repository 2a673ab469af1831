#!/usr/bin/env python3
"""Structural check of firmware/systemd/kerf.service, run everywhere (the
CI image may have no systemd-analyze): the syntax of every line, and the
settings the controller's safety and real time depend on.

    check_unit.py kerf.service
"""
import re
import sys

SECTIONS = ("Unit", "Service", "Install")
# Keys a unit may give more than once (each adds to a list).
LISTS = {"DeviceAllow", "EnvironmentFile", "Wants", "After", "Documentation"}


def parse(path):
    units = {s: {} for s in SECTIONS}
    section = None
    problems = []
    with open(path, encoding="utf-8") as f:
        for number, raw in enumerate(f, 1):
            line = raw.strip()
            where = f"{path}:{number}"
            if not line or line[0] in "#;":
                continue
            m = re.fullmatch(r"\[(\w+)\]", line)
            if m:
                section = m.group(1)
                if section not in units:
                    problems.append(f"{where}: unknown section [{section}]")
                continue
            m = re.fullmatch(r"([A-Za-z]+)=(.*)", line)
            if not m or section is None:
                problems.append(f"{where}: not a Key=value line in a section: {line}")
                continue
            key, value = m.group(1), m.group(2).strip()
            values = units.setdefault(section, {}).setdefault(key, [])
            if values and key not in LISTS:
                problems.append(f"{where}: {key} given twice")
            values.append(value)
    return units, problems


def main():
    path = sys.argv[1]
    units, problems = parse(path)
    service = units["Service"]

    def one(key):
        return service.get(key, [None])[-1]

    def expect(key, wanted, why):
        if one(key) != wanted:
            problems.append(f"{path}: [Service] {key}={one(key)}, expected {wanted}: {why}")

    exec_start = one("ExecStart") or ""
    if not exec_start.startswith("/usr/bin/kerf run --config /etc/kerf/kerf.toml "
                                 "--journal /var/lib/kerf/journal "):
        problems.append(f"{path}: ExecStart does not run kerf with the config and journal: {exec_start}")
    if not exec_start.endswith(" ${KERF_JOB}"):
        problems.append(f"{path}: ExecStart must end with the job, ${{KERF_JOB}} (one argument)")
    if "/etc/default/kerf" not in service.get("EnvironmentFile", []):
        problems.append(f"{path}: EnvironmentFile=/etc/default/kerf is missing (it gives KERF_JOB)")
    expect("Restart", "no", "a crashed cutting job must never restart by itself")
    expect("LimitRTPRIO", "99", "the control loop asks for SCHED_FIFO")
    expect("LimitMEMLOCK", "infinity", "the control loop locks its memory")
    expect("StateDirectory", "kerf", "the journal lives in /var/lib/kerf")
    expect("ConfigurationDirectory", "kerf", "the config lives in /etc/kerf")
    expect("DevicePolicy", "closed", "only the devices listed by DeviceAllow")
    for key, why in (("CPUSchedulingPolicy", "kerf sets SCHED_FIFO on its control loop only"),
                     ("User", "device access and real time need root's capabilities")):
        if key in service:
            problems.append(f"{path}: [Service] {key} must not be set: {why}")
    for key in ("RestrictRealtime", "PrivateDevices"):
        if one(key) not in (None, "no", "false"):
            problems.append(f"{path}: [Service] {key}={one(key)} would break kerf (real time, GPIO)")
    devices = [d.split()[0] for d in service.get("DeviceAllow", [])]
    for wanted in ("char-gpiochip", "char-ttyS", "char-ttyUSB"):
        if wanted not in devices:
            problems.append(f"{path}: DeviceAllow={wanted} is missing")
    caps = (one("CapabilityBoundingSet") or "").split()
    for cap in ("CAP_SYS_NICE", "CAP_IPC_LOCK"):
        if cap not in caps:
            problems.append(f"{path}: CapabilityBoundingSet lacks {cap}")
    if units["Install"].get("WantedBy") != ["multi-user.target"]:
        problems.append(f"{path}: [Install] WantedBy=multi-user.target is missing")

    for p in problems:
        print(p, file=sys.stderr)
    if problems:
        return 1
    print(f"{path}: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
