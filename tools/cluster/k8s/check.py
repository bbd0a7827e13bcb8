#!/usr/bin/env python3
"""Checks tile-shards.yaml and merge.yaml by parsing them (python3-yaml).

kubectl and a cluster are not available where the tests run, so nothing here asks an API server
(where one is: `kubectl apply --dry-run=server -f tile-shards.yaml -f merge.yaml`). What it checks
is what a server would not: that the shard Job is Indexed and its pods tile shard
JOB_COMPLETION_INDEX of N where N is the Job's completions, and that the merge uses the shards'
program, output, inputs, options, image and volumes, which a byte-identical merge needs.

    check.py [DIR]        checks DIR/tile-shards.yaml and DIR/merge.yaml (default: beside this)
    check.py --self-test  also checks that broken copies of them are refused
Exit status 1 with the problems listed when any is found.
"""
import copy
import os
import re
import shlex
import sys

try:
    import yaml
except ImportError:
    print("skipped: python3-yaml missing (Debian: python3-yaml)")
    sys.exit(77)

INDEX = "JOB_COMPLETION_INDEX"


def var_names(token):
    return re.findall(r"\$\{?([A-Za-z_][A-Za-z0-9_]*)\}?", token)


def one(docs, kind, errors, where):
    found = [d for d in docs if isinstance(d, dict) and d.get("kind") == kind]
    if len(found) != 1:
        errors.append(f"{where}: {len(found)} {kind} documents, want 1")
        return None
    return found[0]


def container_of(job, errors, where):
    """The Job's only container, or None (with the problem in errors)."""
    if job.get("apiVersion") != "batch/v1":
        errors.append(f"{where}: apiVersion {job.get('apiVersion')!r}, want batch/v1")
    pod = (((job.get("spec") or {}).get("template") or {}).get("spec")) or {}
    if pod.get("restartPolicy") not in ("Never", "OnFailure"):
        errors.append(f"{where}: restartPolicy must be Never or OnFailure for a Job")
    containers = pod.get("containers") or []
    if len(containers) != 1:
        errors.append(f"{where}: {len(containers)} containers, want 1")
        return None, pod
    volumes = {v.get("name") for v in pod.get("volumes") or []}
    for mount in containers[0].get("volumeMounts") or []:
        if mount.get("name") not in volumes:
            errors.append(f"{where}: volumeMount {mount.get('name')!r} has no volume")
    return containers[0], pod


def script_tokens(container, errors, where):
    """The words of the container's `sh -c` script, or of its command when it has none."""
    command = list(container.get("command") or []) + list(container.get("args") or [])
    if len(command) >= 3 and os.path.basename(str(command[0])) in ("sh", "bash") and command[1] == "-c":
        try:
            words = shlex.split(str(command[2]))
        except ValueError as e:
            errors.append(f"{where}: the shell script does not parse: {e}")
            return []
    else:
        words = [str(w) for w in command]
    if words[:1] == ["exec"]:
        words = words[1:]
    if not words:
        errors.append(f"{where}: no command")
    return words


def env_of(container):
    return {e.get("name"): e.get("value") for e in container.get("env") or []}


def check(shards_docs, merge_docs):
    errors = []
    w = "tile-shards.yaml"
    job = one(shards_docs, "Job", errors, w)
    merge = one(merge_docs, "Job", errors, "merge.yaml")
    if job is None or merge is None:
        return errors
    spec = job.get("spec") or {}
    if spec.get("completionMode") != "Indexed":
        errors.append(f"{w}: completionMode {spec.get('completionMode')!r}, want Indexed")
    n = spec.get("completions")
    if not isinstance(n, int) or n < 1:
        errors.append(f"{w}: completions {n!r} is not a shard count")
        n = None
    p = spec.get("parallelism", 1)
    if not isinstance(p, int) or p < 1 or (n is not None and p > n):
        errors.append(f"{w}: parallelism {p!r} must be 1..completions")
    shard_c, shard_pod = container_of(job, errors, w)
    merge_c, merge_pod = container_of(merge, errors, "merge.yaml")
    if shard_c is None or merge_c is None:
        return errors
    shard_env, merge_env = env_of(shard_c), env_of(merge_c)
    if INDEX in shard_env:
        errors.append(f"{w}: env sets {INDEX}, which hides the one Kubernetes sets")

    # The shard: `PROGRAM ... --shard $JOB_COMPLETION_INDEX/N ...`, N being completions.
    words = script_tokens(shard_c, errors, w)
    if words.count("--shard") != 1 or words.index("--shard") + 1 >= len(words):
        errors.append(f"{w}: the command has no --shard K/N")
        return errors
    at = words.index("--shard")
    k, _, count = words[at + 1].partition("/")
    if var_names(k) != [INDEX]:
        errors.append(f"{w}: --shard {words[at + 1]!r}: K must be ${INDEX}")
    names = var_names(count)
    if names:
        value = shard_env.get(names[0])
        if len(names) != 1 or value is None:
            errors.append(f"{w}: --shard {words[at + 1]!r}: N must be one variable set in env")
        elif n is not None and str(value) != str(n):
            errors.append(f"{w}: --shard N is {names[0]}={value!r} but completions is {n}")
    elif n is not None and count != str(n):
        errors.append(f"{w}: --shard N is {count!r} but completions is {n}")
    shard_rest = words[:at] + words[at + 2:]

    # The merge: `PROGRAM merge ...` with the shards' other words.
    mw = "merge.yaml"
    mspec = merge.get("spec") or {}
    if mspec.get("completionMode", "NonIndexed") != "NonIndexed":
        errors.append(f"{mw}: the merge must not be Indexed")
    if mspec.get("completions", 1) != 1 or mspec.get("parallelism", 1) != 1:
        errors.append(f"{mw}: the merge runs once: completions and parallelism 1")
    mwords = script_tokens(merge_c, errors, mw)
    if len(mwords) < 2 or mwords[1] != "merge" or "--shard" in mwords:
        errors.append(f"{mw}: the command must be `PROGRAM merge ...` without --shard")
    elif mwords[:1] + mwords[2:] != shard_rest:
        errors.append(f"{mw}: the merge's words {mwords[:1] + mwords[2:]} differ from the "
                      f"shards' {shard_rest} (program, output, inputs and options must match)")
    for name in sorted({v for t in shard_rest for v in var_names(t)}):
        if shard_env.get(name) != merge_env.get(name):
            errors.append(f"{mw}: {name}={merge_env.get(name)!r}, the shards have "
                          f"{shard_env.get(name)!r}")
    if shard_c.get("image") != merge_c.get("image"):
        errors.append(f"{mw}: image {merge_c.get('image')!r} is not the shards' {shard_c.get('image')!r}")
    if (shard_pod.get("volumes"), shard_c.get("volumeMounts")) != \
            (merge_pod.get("volumes"), merge_c.get("volumeMounts")):
        errors.append(f"{mw}: volumes or volumeMounts differ from the shards'")

    # The output on a claim every pod can write, and the claim and ConfigMap defined.
    claims = {d.get("metadata", {}).get("name"): d for d in shards_docs
              if isinstance(d, dict) and d.get("kind") == "PersistentVolumeClaim"}
    maps = {d.get("metadata", {}).get("name"): d for d in shards_docs
            if isinstance(d, dict) and d.get("kind") == "ConfigMap"}
    vols = {v.get("name"): v for v in shard_pod.get("volumes") or []}
    out = None
    if "-o" in shard_rest and shard_rest.index("-o") + 1 < len(shard_rest):
        out = shard_rest[shard_rest.index("-o") + 1]
        for name in var_names(out):
            out = out.replace("${%s}" % name, str(shard_env.get(name))).replace(
                "$" + name, str(shard_env.get(name)))
    else:
        errors.append(f"{w}: the command has no -o OUT")
    on_claim = False
    for mount in shard_c.get("volumeMounts") or []:
        vol = vols.get(mount.get("name")) or {}
        mount_path = str(mount.get("mountPath", "")).rstrip("/") + "/"
        if "persistentVolumeClaim" in vol and out and out.startswith(mount_path):
            on_claim = True
            claim = claims.get(vol["persistentVolumeClaim"].get("claimName"))
            if claim is None:
                errors.append(f"{w}: claim {vol['persistentVolumeClaim'].get('claimName')!r} "
                              "is not defined")
            elif "ReadWriteMany" not in (claim.get("spec") or {}).get("accessModes", []):
                errors.append(f"{w}: the output's claim must be ReadWriteMany (pods on several nodes)")
        if "configMap" in vol and vol["configMap"].get("name") not in maps:
            errors.append(f"{w}: ConfigMap {vol['configMap'].get('name')!r} is not defined")
    if out and not on_claim:
        errors.append(f"{w}: OUT {out!r} is not on a PersistentVolumeClaim mount")
    return errors


def load(path):
    with open(path, encoding="utf-8") as f:
        return [d for d in yaml.safe_load_all(f) if d is not None]


def self_test(shards_docs, merge_docs):
    """Each broken copy must be refused: a check that cannot fail proves nothing."""
    def job(docs):
        return next(d for d in docs if d.get("kind") == "Job")

    def container(docs):
        return job(docs)["spec"]["template"]["spec"]["containers"][0]

    def env(docs, name, value):
        for e in container(docs)["env"]:
            if e["name"] == name:
                e["value"] = value

    def script(docs, old, new):
        c = container(docs)
        c["command"][2] = c["command"][2].replace(old, new)

    breakages = {
        "completions without SHARDS": lambda s, m: job(s)["spec"].update(completions=5),
        "not Indexed": lambda s, m: job(s)["spec"].pop("completionMode"),
        "index not used": lambda s, m: script(s, "$" + INDEX, "0"),
        "misspelt index": lambda s, m: script(s, INDEX, "JOB_INDEX"),
        "parallelism above completions": lambda s, m: job(s)["spec"].update(parallelism=99),
        "merge options differ": lambda s, m: env(m, "TILER_OPTS", "--pack-tiles 8 -q"),
        "merge output differs": lambda s, m: env(m, "OUT", "/pyramid/other"),
        "merge without merge": lambda s, m: script(m, " merge ", " "),
        "merge sharded": lambda s, m: script(m, " merge ", " --shard 0/1 "),
        "merge image differs": lambda s, m: container(m).update(image="other:1"),
        "merge on another claim": lambda s, m: job(m)["spec"]["template"]["spec"]["volumes"][0]
        ["persistentVolumeClaim"].update(claimName="other"),
        "claim ReadWriteOnce": lambda s, m: next(d for d in s if d["kind"] == "PersistentVolumeClaim")
        ["spec"].update(accessModes=["ReadWriteOnce"]),
        "shard Job a Deployment": lambda s, m: job(s).update(kind="Deployment"),
        "restartPolicy Always": lambda s, m: job(s)["spec"]["template"]["spec"].update(
            restartPolicy="Always"),
    }
    missed = []
    for name, breakage in breakages.items():
        s, m = copy.deepcopy(shards_docs), copy.deepcopy(merge_docs)
        breakage(s, m)
        if not check(s, m):
            missed.append(name)
    return [f"self-test: a broken copy passed: {name}" for name in missed], len(breakages)


def main(argv):
    args = [a for a in argv if a != "--self-test"]
    directory = args[0] if args else os.path.dirname(os.path.abspath(__file__))
    try:
        shards_docs = load(os.path.join(directory, "tile-shards.yaml"))
        merge_docs = load(os.path.join(directory, "merge.yaml"))
    except (OSError, yaml.YAMLError) as e:
        print(f"FAIL: {e}")
        return 1
    errors = check(shards_docs, merge_docs)
    refused = ""
    if not errors and "--self-test" in argv:
        errors, count = self_test(shards_docs, merge_docs)
        refused = f" ({count} broken copies refused)"
    for e in errors:
        print(f"FAIL: {e}")
    if not errors:
        print("OK: tile-shards.yaml and merge.yaml" + refused)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
