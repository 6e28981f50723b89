"""procex's worker threads in this process, as /proc/self/task lists them:
what the tests of procex.batch_iter (tests/python) and of the Blender add-on
(tests/blender, which puts this folder on its path) check is left once an
iterator is closed."""
import os
import time


def workers():
    """How many threads are named procex-batch, as batch_iter names its
    worker. With jobs=1 it evaluates on that thread alone; with more, TBB's
    pool of workers is the process's, kept or ended as TBB decides, and a
    worker it starts from there inherits the name."""
    names = []
    for task in os.listdir("/proc/self/task"):
        try:
            names.append(open(f"/proc/self/task/{task}/comm").read().strip())
        except FileNotFoundError:  # a thread that has just ended
            pass
    return names.count("procex-batch")


def workers_once_joined(at_most):
    """workers() once those the iterator joined have left /proc: pthread_join
    returns when the kernel wakes it, as the thread lets go of its memory,
    and the task is unlisted a moment later, so a count taken at once can
    still see a joined worker (a C loop of create, join, list: 1 in 20,000
    still listed, beside two soak runs; test_batch_iter failed once so
    loaded). Waits up to 10 s for the count to fall to at_most."""
    deadline = time.monotonic() + 10
    while workers() > at_most and time.monotonic() < deadline:
        time.sleep(0.01)
    return workers()
