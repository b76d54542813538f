#!/usr/bin/env python3
"""Before and after, every shipped scene: `gloss bench` per pass, two binaries.

Runs `gloss bench` on every scenes/*.toml with an OLD and a NEW gloss binary,
interleaved (old, new, old, new, ...: the machine is shared and noisy, so the
ratios come from one sitting), and writes one table per scene and pass: old
ms, new ms, new/old. A row slower by more than the noise is flagged and its
setting rerun alone, interleaved again with more frames, before it is called
slower.

Each scene runs on its own path as written (`--vary render.path=<its path>`,
so its other settings stay as the file says). The scenes where comparing
lighting paths means something (default, logl-like, many-lights, and every
scene whose own path is not forward) also run on every lighting path
(`--paths forward,deferred,volumes,prepass,tiled`; deferred runs both of its
forms). Both binaries read the same, current scene file; settings the old
binary did not have are left at the new binary's defaults (what a user gets).
A scene the old binary cannot load is reported as such, with its error.

    python3 tools/before_after.py --old /work/wt/old-gloss --new target/release/gloss
    python3 tools/before_after.py --report-only   # re-make the page from the CSVs kept

Every run's CSV stays under --work (target/before-after/), so the page can be
re-made without measuring again. Only the Python standard library is used.
"""

import argparse
import csv
import glob
import json
import os
import statistics
import subprocess
import sys
import time
import tomllib

ALL_PATHS = "forward,deferred,volumes,prepass,tiled"
# Scenes compared on every lighting path besides their own (and every scene
# whose own path is a deferred one).
ALL_PATH_SCENES = {"default", "logl-like", "many-lights", "model-loading"}
FRAME = "(frame)"


def scene_info(path):
    """The scene's own render path and size, as the file says (defaults:
    forward, 1280x720, as src/scene/file.rs has them)."""
    with open(path, "rb") as f:
        doc = tomllib.load(f)
    render = doc.get("render", {})
    own = render.get("path", "forward")
    size = tuple(render.get("size", [1280, 720]))
    return own, size


def jobs_for(scene, size_cap, every):
    """(job name, bench arguments) for one scene; `every`: "auto" (the
    scenes named above), "none" or "only" (the every-path job alone)."""
    name = os.path.splitext(os.path.basename(scene))[0]
    own, size = scene_info(scene)
    w, h = size
    if w * h > size_cap[0] * size_cap[1]:
        w, h = size_cap
    common = ["--size", f"{w}x{h}"]
    jobs = []
    if every != "only":
        jobs.append(("own path", ["--vary", f"render.path={own}"] + common))
    if every != "none" and (name in ALL_PATH_SCENES or own != "forward"):
        jobs.append(("every path", ["--paths", ALL_PATHS] + common))
    return name, own, (w, h), jobs


def read_csv(path):
    """{setting: {pass: median ms}}, the frame's median under FRAME."""
    out = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            passes = {FRAME: float(row["frame_median_ms"])}
            for k, v in row.items():
                if k.startswith("pass_") and k.endswith("_median_ms") and v:
                    passes[k[len("pass_") : -len("_median_ms")]] = float(v)
            out[row["setting"]] = passes
    return out


def run_bench(binary, scene, args, frames, warmup, out, timeout):
    """One `gloss bench` run; its CSV parsed, or the first error line."""
    os.makedirs(out, exist_ok=True)
    cmd = [binary, "bench", scene, *args, "--frames", str(frames)]
    cmd += ["--warmup", str(warmup), "--out", out]
    env = dict(os.environ)
    env.setdefault("MESA_GL_VERSION_OVERRIDE", "3.3")
    env.setdefault("MESA_GLSL_VERSION_OVERRIDE", "330")
    t0 = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"error": f"no result within {timeout} s", "cmd": cmd}
    with open(os.path.join(out, "stdout.txt"), "w") as f:
        f.write(p.stdout)
    with open(os.path.join(out, "stderr.txt"), "w") as f:
        f.write(p.stderr)
    csv_path = os.path.join(out, "bench.csv")
    if p.returncode != 0 or not os.path.exists(csv_path):
        lines = [l for l in p.stderr.splitlines() if l.strip()]
        err = next((l for l in lines if "rror" in l), lines[-1] if lines else f"exit {p.returncode}")
        return {"error": err.strip(), "cmd": cmd}
    return {"settings": read_csv(csv_path), "seconds": time.time() - t0, "cmd": cmd}


def measure(binaries, scene, args, frames, warmup, reps, work, tag, timeout):
    """old, new, old, new, ...: {which: [run, ...]}."""
    runs = {"old": [], "new": []}
    for rep in range(reps):
        for which in ("old", "new"):
            out = os.path.join(work, f"{which}-{tag}-{rep}")
            r = run_bench(binaries[which], scene, args, frames, warmup, out, timeout)
            runs[which].append(r)
            if "error" in r:
                print(f"    {which}: {r['error']}", file=sys.stderr)
                if which == "old" and rep == 0:
                    # The old binary cannot run it: measure the new once, no more.
                    out = os.path.join(work, f"new-{tag}-0")
                    runs["new"].append(
                        run_bench(binaries["new"], scene, args, frames, warmup, out, timeout)
                    )
                    return runs
    return runs


def pair_renamed(old, new):
    """A pass renamed since: the old "shadow map" is today's "shadow map
    (light 2)", or the sum of a cube's six "shadow map (light 0, face +X)"
    passes. An old-only pass meets the sum of the new-only passes whose
    name is its own followed by " (" (the old binary summed passes of one
    name in a frame). `old` and `new`: {(setting, pass): [ms per run]}."""
    for s, p in [k for k in old if k not in new]:
        parts = [k for k in new if k[0] == s and k[1].startswith(p + " (") and k not in old]
        if parts and len({len(new[k]) for k in parts}) == 1:
            label = parts[0][1] if len(parts) == 1 else f"{p} (sum of {len(parts)})"
            new[(s, f"{p} → {label}")] = [sum(v) for v in zip(*(new[k] for k in parts))]
            old[(s, f"{p} → {label}")] = old.pop((s, p))
            for k in parts:
                del new[k]


def paired(rows):
    """Stored rows with pair_renamed applied, in the order of the settings."""
    old = {(s, p): o for s, p, o, n in rows if o}
    new = {(s, p): n for s, p, o, n in rows if n}
    pair_renamed(old, new)
    order = []
    for s, p, o, n in rows:
        if s not in order:
            order.append(s)
    keys = [k for k in dict.fromkeys(list(old) + list(new))]
    keys.sort(key=lambda k: order.index(k[0]))
    return [(s, p, old.get((s, p), []), new.get((s, p), [])) for s, p in keys]


def rows_of(runs):
    """[(setting, pass, [old ms...], [new ms...])] for the settings and passes
    in either binary's runs."""
    def collect(which):
        d = {}
        for r in runs[which]:
            for s, passes in r.get("settings", {}).items():
                for p, v in passes.items():
                    d.setdefault((s, p), []).append(v)
        return d

    old, new = collect("old"), collect("new")
    pair_renamed(old, new)
    keys = []
    for k in list(old) + list(new):
        if k not in keys:
            keys.append(k)
    return [(s, p, old.get((s, p), []), new.get((s, p), [])) for s, p in keys]


def verdict(old, new, min_ratio, min_ms):
    """'slower?' when the new median exceeds the old by more than the noise:
    min_ratio, twice the relative spread of either binary's runs, and min_ms."""
    if not old or not new:
        return ""
    o, n = statistics.median(old), statistics.median(new)
    if o <= 0:
        return ""
    spread = max((max(v) - min(v)) / max(statistics.median(v), 1e-9) for v in (old, new))
    if n / o > 1 + max(min_ratio - 1, 2 * spread) and n - o > min_ms:
        return "slower?"
    return ""


def fmt_ms(v):
    if not v:
        return "—"
    m = statistics.median(v)
    return f"{m:.2f}" if m < 100 else f"{m:.0f}"


def rerun_args(job_args, setting):
    """The bench arguments that measure one setting of a job alone: for an
    `--paths` job, that setting's path only (deferred's two forms come
    together); a `--vary` job is one setting already."""
    if "--paths" not in job_args:
        return job_args
    path = setting.split()[0].split("+")[0]
    i = job_args.index("--paths")
    return job_args[:i] + ["--paths", path] + job_args[i + 2 :]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--old", default="/work/wt/old-gloss", help="the old gloss binary")
    ap.add_argument("--new", default="target/release/gloss", help="the new gloss binary")
    ap.add_argument("--scenes", nargs="*", help="scene files (default: scenes/*.toml)")
    ap.add_argument("--size", default="640x360", help="largest size; smaller scenes keep theirs")
    ap.add_argument("--frames", type=int, default=4)
    ap.add_argument("--warmup", type=int, default=1)
    ap.add_argument("--reps", type=int, default=2, help="old/new pairs per scene")
    ap.add_argument("--rerun-frames", type=int, default=12)
    ap.add_argument("--rerun-reps", type=int, default=3)
    ap.add_argument(
        "--every",
        choices=["auto", "none", "only"],
        default="auto",
        help="the every-path job: where meaningful (auto), never, or alone",
    )
    ap.add_argument("--min-ratio", type=float, default=1.10)
    ap.add_argument("--min-ms", type=float, default=0.10)
    ap.add_argument("--timeout", type=int, default=300, help="seconds per bench run")
    ap.add_argument("--work", default="target/before-after")
    ap.add_argument("--page", default="target/before-after/tables.md")
    ap.add_argument("--report-only", action="store_true", help="re-make the page from --work")
    a = ap.parse_args()
    cap = tuple(int(x) for x in a.size.lower().split("x"))
    scenes = a.scenes or sorted(glob.glob("scenes/*.toml"))
    state_path = os.path.join(a.work, "results.json")
    os.makedirs(a.work, exist_ok=True)
    if a.report_only:
        with open(state_path) as f:
            state = json.load(f)
    else:
        binaries = {"old": a.old, "new": a.new}
        for b in binaries.values():
            if not os.access(b, os.X_OK):
                sys.exit(f"before_after: {b}: not an executable gloss binary")
        # Results accumulate in results.json: a run adds or replaces the
        # jobs it measures, so the sitting can be split and resumed.
        state = {"scenes": [], "loads": []}
        if os.path.exists(state_path):
            with open(state_path) as f:
                state = json.load(f)
        state["args"] = vars(a)
        state["loads"].append(open("/proc/loadavg").read().split()[:3])
        for scene in scenes:
            name, own, size, jobs = jobs_for(scene, cap, a.every)
            entry = next((e for e in state["scenes"] if e["name"] == name), None)
            if entry is None:
                entry = {"name": name, "own": own, "size": size, "jobs": []}
                state["scenes"].append(entry)
            for job, args in jobs:
                print(f"{name}: {job}", file=sys.stderr)
                work = os.path.join(a.work, name, job.replace(" ", "-"))
                runs = measure(binaries, scene, args, a.frames, a.warmup, a.reps, work, "a", a.timeout)
                rows = rows_of(runs)
                flagged = {}
                for s, p, o, n in rows:
                    if verdict(o, n, a.min_ratio, a.min_ms):
                        flagged.setdefault(s, []).append(p)
                # One rerun per set of arguments (deferred's two forms share one).
                groups = {}
                for s in flagged:
                    print(f"  rerun {s}: {', '.join(flagged[s])}", file=sys.stderr)
                    groups.setdefault(tuple(rerun_args(args, s)), []).append(s)
                reruns = {}
                for rargs, settings in groups.items():
                    tag = "rerun-" + "".join(c if c.isalnum() else "_" for c in settings[0])
                    rr = measure(binaries, scene, list(rargs), a.rerun_frames, a.warmup, a.rerun_reps, work, tag, a.timeout)
                    for s in settings:
                        reruns[s] = {"args": list(rargs), "rows": [r for r in rows_of(rr) if r[0] == s]}
                entry["jobs"] = [x for x in entry["jobs"] if x["job"] != job]
                entry["jobs"].append({
                    "job": job,
                    "args": args,
                    "errors": {w: [r["error"] for r in runs[w] if "error" in r] for w in runs},
                    "rows": rows,
                    "reruns": reruns,
                    "frames": a.frames,
                    "reps": a.reps,
                    "min_ratio": a.min_ratio,
                    "min_ms": a.min_ms,
                    "rerun": [a.rerun_frames, a.rerun_reps],
                    "load": open("/proc/loadavg").read().split()[:3],
                })
                entry["jobs"].sort(key=lambda x: x["job"] != "own path")
                with open(state_path, "w") as f:
                    json.dump(state, f)
        state["loads"].append(open("/proc/loadavg").read().split()[:3])
        with open(state_path, "w") as f:
            json.dump(state, f)
    page = render(state, a)
    os.makedirs(os.path.dirname(a.page) or ".", exist_ok=True)
    with open(a.page, "w") as f:
        f.write(page)
    print(f"wrote {a.page}", file=sys.stderr)


def plain(err):
    """An error line as page text: no backticks, no `error: ` prefix."""
    return err.replace("`", "'").removeprefix("error: ")


def render(state, a):
    """The markdown tables: a summary, then one table per scene."""
    out = []
    args = state["args"]
    loads = ", ".join("/".join(l) for l in state["loads"])
    out.append(
        f"Load averages (1/5/15 min) when each sitting started or ended: {loads}. "
        f"Times are medians in ms; the ratio is new/old. Each table says its "
        f"frames, pairs, threshold and reruns.\n"
    )
    slower, frames, only, failed = [], [], [], []
    body = []
    for e in sorted(state["scenes"], key=lambda e: e["name"]):
        w, h = e["size"]
        body.append(f"\n### {e['name']} ({e['own']}, {w}x{h})\n")
        for j in e["jobs"]:
            if j["errors"]["old"]:
                failed.append((e["name"], j["job"], j["errors"]["old"][0]))
                body.append(f"\n{j['job']}: the old binary cannot run it: \"{plain(j['errors']['old'][0])}\"\n")
            if j["errors"]["new"]:
                body.append(f"\n{j['job']}: the new binary failed: \"{plain(j['errors']['new'][0])}\"\n")
            rows = [r for r in paired(j["rows"]) if r[2] or r[3]]
            if not rows or j["errors"]["old"]:
                continue
            lim = (j.get("min_ratio", args["min_ratio"]), j.get("min_ms", args["min_ms"]))
            rf, rp = j.get("rerun", [args["rerun_frames"], args["rerun_reps"]])
            body.append(
                f"\n{j['job']} (`{' '.join(j['args'])}`, {j['frames']} frames, "
                f"{j['reps']} pairs, load {j['load'][0]}; flagged above {lim[0]:.2f}x, "
                f"reruns {rf} frames, {rp} pairs):\n"
            )
            body.append("| setting | pass | old ms | new ms | new/old | |")
            body.append("|---|---|---|---|---|---|")
            for s, p, o, n in rows:
                ratio = statistics.median(n) / statistics.median(o) if o and n and statistics.median(o) > 0 else None
                flag = verdict(o, n, *lim)
                if flag and s in j["reruns"]:
                    rr = {(rs, rp): (ro, rn) for rs, rp, ro, rn in paired(j["reruns"][s]["rows"])}
                    if (s, p) in rr:
                        ro, rn = rr[(s, p)]
                        again = verdict(ro, rn, *lim)
                        rratio = statistics.median(rn) / statistics.median(ro) if ro and rn else float("nan")
                        flag = (
                            f"**slower**: rerun {fmt_ms(ro)} → {fmt_ms(rn)} ({rratio:.2f})"
                            if again
                            else f"noise: rerun {fmt_ms(ro)} → {fmt_ms(rn)} ({rratio:.2f})"
                        )
                        if again:
                            slower.append((e["name"], s, p, fmt_ms(ro), fmt_ms(rn), rratio))
                    else:
                        flag = "rerun has no such pass"
                if flag == "slower?":
                    flag = "slower? (not rerun alone)"
                if not o:
                    flag = "new only"
                    only.append((e["name"], s, p, "new"))
                elif not n:
                    flag = "old only"
                    only.append((e["name"], s, p, "old"))
                if ratio is not None and p == FRAME:
                    frames.append((e["name"], s, fmt_ms(o), fmt_ms(n), ratio, flag))
                rtxt = f"{ratio:.2f}" if ratio is not None else "—"
                label = "**frame**" if p == FRAME else p
                body.append(f"| {s} | {label} | {fmt_ms(o)} | {fmt_ms(n)} | {rtxt} | {flag} |")
    out.append("\nSlower after the rerun (scene, setting, pass, old ms, new ms, ratio):\n")
    if slower:
        out.append("| scene | setting | pass | old ms | new ms | new/old |\n|---|---|---|---|---|---|")
        for r in slower:
            out.append(f"| {r[0]} | {r[1]} | {r[2]} | {r[3]} | {r[4]} | {r[5]:.2f} |")
    else:
        out.append("none.")
    out.append("\nWhole frames (scene, setting, old ms, new ms, new/old; a flag as in the tables below):\n")
    out.append("| scene | setting | old ms | new ms | new/old | |\n|---|---|---|---|---|---|")
    for r in frames:
        out.append(f"| {r[0]} | {r[1]} | {r[2]} | {r[3]} | {r[4]:.2f} | {r[5]} |")
    if failed:
        out.append("\nScenes the old binary cannot run (so no before):\n")
        for n, j, err in failed:
            out.append(f"- {n} ({j}): \"{plain(err)}\"")
    done = {e["name"] for e in state["scenes"]}
    missing = [
        os.path.splitext(os.path.basename(f))[0]
        for f in sorted(glob.glob("scenes/*.toml"))
        if os.path.splitext(os.path.basename(f))[0] not in done
    ]
    if missing:
        out.append("\nScenes not measured in this sitting: " + ", ".join(missing) + ".")
    out.append("\n" + "\n".join(body))
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    main()
