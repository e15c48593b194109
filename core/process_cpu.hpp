#pragma once
// The CPU time this process has used (getrusage: user + system, every thread), seconds. A run
// records the difference over its synthesis (run.json's cpu_seconds): unlike its wall time it
// does not grow when other runs share the cores, so a sweep of several runs at once still
// says what each run's work costs (docs/howto/reproduce_a_figure.md, timing rules).
namespace ppsynth {

double process_cpu_seconds();

}  // namespace ppsynth
