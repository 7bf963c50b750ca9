"""The task pool (src/electrogrowth/pool.py): every task's result comes back once, with
its index, in this process and on a process pool; bad worker counts are one-line errors."""

from __future__ import annotations

import operator

import pytest

from electrogrowth.errors import UsageError
from electrogrowth.pool import WORKERS_PER_CORE, check_workers, run_tasks, usable_cores


@pytest.mark.parametrize("workers", [1, 2])
def test_every_task_once_with_its_index(workers):
    tasks = [3, -1, 4, 1, -5]
    out = list(run_tasks(operator.neg, tasks, workers=workers))
    assert sorted(i for i, _ in out) == list(range(len(tasks)))
    assert all(result == -tasks[i] for i, result in out)


def test_in_process_keeps_the_order_and_runs_lazily():
    seen = []

    def note(x):
        seen.append(x)
        return x

    results = run_tasks(note, ["a", "b"])
    assert seen == []  # nothing runs before the caller reads
    assert list(results) == [(0, "a"), (1, "b")]
    assert list(run_tasks(note, [])) == []


@pytest.mark.parametrize("workers", [0, -2, 1.5, True, WORKERS_PER_CORE * 64 + 1])
def test_bad_workers_name_the_range(workers):
    with pytest.raises(UsageError, match=rf"--workers {workers} is out of range; need 1 to"):
        check_workers(workers)
    check_workers(usable_cores())
