"""The results table (Markdown) and the plots (PNG) under bench/results/."""

from __future__ import annotations

import datetime
import os
import platform
from pathlib import Path

import matplotlib

matplotlib.use('Agg')  # files only: the benchmarks run headless
import matplotlib.pyplot as plt

from common import RESULTS, Row


def machine() -> str:
    model = next((line.split(':', 1)[1].strip() for line in
                  Path('/proc/cpuinfo').read_text().splitlines()
                  if line.startswith('model name')), platform.processor())
    memory_gib = os.sysconf('SC_PAGE_SIZE') * os.sysconf('SC_PHYS_PAGES') / 2**30
    return (f'{model}, {os.cpu_count()} cores, {memory_gib:.0f} GiB, {platform.system()} '
            f'{platform.release()}, Python {platform.python_version()}')


def table(rows: list[Row]) -> str:
    lines = ['| benchmark | metric | value | target | verdict |', '|---|---|---|---|---|']
    lines += [f'| {r.benchmark} | {r.metric} | {r.value} | {r.target} | {r.verdict} |'
              for r in rows]
    return '\n'.join(lines)


def write_markdown(rows: list[Row], seconds: float) -> Path:
    when = datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d %H:%M UTC')
    text = (f'# Benchmark results\n\n{when}, on {machine()}; the whole run took {seconds:.0f} s.\n'
            f'Every figure is from this one run; ratios compare with baselines run alongside.\n\n'
            f'{table(rows)}\n')
    path = RESULTS / 'results.md'
    path.write_text(text)
    return path


def write_plots(data: dict) -> list[Path]:
    written = []
    if 'roundtrip' in data:
        fig, ax = plt.subplots(figsize=(6, 4))
        for label, samples in data['roundtrip'].items():
            ordered = sorted(samples)
            ax.plot(ordered, [i / len(ordered) for i in range(len(ordered))], label=label)
        ax.set(xlabel='round trip (ms)', ylabel='fraction of calls', xscale='log',
               title='Service round trip, same client, same run')
        ax.legend()
        written.append(_save(fig, 'roundtrip_cdf.png'))
    if 'latency' in data:
        fig, ax = plt.subplots(figsize=(6, 4))
        for label, samples in data['latency'].items():
            ax.hist(samples, bins=60, alpha=0.6, label=label)
        ax.set(xlabel='publish to callback (ms)', ylabel='poses',
               title='Pose latency, same subscriber, same run')
        ax.legend()
        written.append(_save(fig, 'pose_latency.png'))
    scale = [r for r in data.get('scale', []) if 'error' not in r and not r.get('sink')]
    if scale:
        counts = [r['count'] for r in scale]
        fig, (rate_ax, tick_ax) = plt.subplots(1, 2, figsize=(10, 4))
        rate_ax.plot(counts, [r['rate_min'] for r in scale], 'o-', label='slowest sampled turtle')
        rate_ax.plot(counts, [r['rate_mean'] for r in scale], 's--', label='mean of sampled')
        rate_ax.axhline(62.5, color='grey', linestyle=':', label='62.5 Hz')
        rate_ax.set(xlabel='turtles', ylabel='pose rate per turtle (Hz)', title='Pose rate')
        rate_ax.legend()
        tick_ax.plot(counts, [r['tick_mean_ms'] for r in scale], 'o-', label='mean')
        tick_ax.plot(counts, [r['tick_p99_ms'] for r in scale], 's--', label='p99')
        tick_ax.axhline(16.0, color='grey', linestyle=':', label='16 ms period')
        tick_ax.set(xlabel='turtles', ylabel='tick cost (ms)', title='Tick cost')
        tick_ax.legend()
        written.append(_save(fig, 'scale.png'))
    return written


def _save(fig, name: str) -> Path:
    path = RESULTS / name
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path
