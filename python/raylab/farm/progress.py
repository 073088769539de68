"""The farm's progress line on stderr: jobs, samples, elapsed time and ETA. On a terminal one line redrawn in
place with a bar; otherwise (logs, CI) one line per finished job."""
import sys
import time

BAR_WIDTH = 24


def _duration(seconds: float) -> str:
    if seconds < 60:
        return f"{seconds:.1f} s"
    minutes, seconds = divmod(int(seconds + 0.5), 60)
    if minutes < 60:
        return f"{minutes} min {seconds:02d} s"
    hours, minutes = divmod(minutes, 60)
    return f"{hours} h {minutes:02d} min"


class Progress:
    def __init__(self, label: str, jobs: int, samples_per_job: int, already_done: int, enabled: bool = True,
                 stream=None):
        self.label = label
        self.jobs = jobs
        self.samples_per_job = samples_per_job
        self.done = already_done
        self.already_done = already_done
        self.enabled = enabled
        self.stream = stream or sys.stderr
        self.in_place = self.stream.isatty()
        self.start = time.monotonic()

    def job_done(self):
        self.done += 1
        self.show()

    def show(self):
        if not self.enabled:
            return
        elapsed = time.monotonic() - self.start
        rendered = self.done - self.already_done
        remaining = self.jobs - self.done
        # The rate of this run's jobs (jobs finished by an earlier run cost nothing now).
        eta = f"ETA {_duration(elapsed / rendered * remaining)}" if rendered and remaining else ""
        filled = BAR_WIDTH * self.done // max(1, self.jobs)
        # Jobs that are not renders (samples_per_job 0: a fit) have no samples to count.
        samples = (f"{self.done * self.samples_per_job}/{self.jobs * self.samples_per_job} spp  "
                   if self.samples_per_job else "")
        line = (f"{self.label} [{'#' * filled}{'-' * (BAR_WIDTH - filled)}] {self.done}/{self.jobs} jobs  "
                f"{samples}{_duration(elapsed)}  {eta}").rstrip()
        if self.in_place:
            self.stream.write("\r\033[K" + line)
            if self.done == self.jobs:
                self.stream.write("\n")
        else:
            self.stream.write(line + "\n")
        self.stream.flush()
