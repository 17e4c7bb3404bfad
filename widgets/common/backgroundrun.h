#pragma once
// One way to run a long computation off the GUI thread: BackgroundRun<R> runs a job
// `R job(RunObserver&)` on the global thread pool (QtConcurrent), delivers its progress queued to
// the GUI thread (throttled) and ends with exactly one of finished(), cancelled() or failed().
//
//  * The job gets a RunObserver: an Observer (core/common/run.h) that forwards each iteration's
//    IterationSummary::progress and stops the method once cancel() was called; pass it to the
//    core's methods as their Observer*. report() posts a fraction with a text of the job's own.
//  * Cancellation is the core's CancelToken; a job that returns after cancel() ends with
//    cancelled() instead of finished(), and what it returned (a method's best so far) is the result.
//  * An exception thrown by the job ends the run with failed(what()); there is no result then.
//  * The result is delivered once: takeResult() moves it out, a second call gives nothing.
//  * setSynchronous(true) runs the job on the calling thread inside start() (tests, scripted
//    runs): the same signals in the same order, progress emitted directly.
#include <QObject>
#include <QString>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

#include "core/common/run.h"

template <typename T>
class QFutureWatcher;

namespace metrofit {

class BackgroundRunBase;

/// The observer a background job is given; its methods may be called from the worker thread.
class RunObserver final : public Observer {
 public:
  /// Reports summary.progress (when known) and returns Stop once the run was cancelled.
  ObserverDecision onIteration(const IterationSummary& summary) override;
  /// Reports a fraction in [0, 1] (clamped; a negative one keeps the last fraction) with a text.
  void report(double fraction, const QString& text = {});
  /// True once cancel() was called on the run.
  bool isCancelled() const noexcept { return token_.isCancelled(); }
  /// The run's cancellation flag (for core functions that take a CancelToken).
  CancelToken& cancelToken() noexcept { return token_; }

 private:
  friend class BackgroundRunBase;
  struct Delivery;
  CancelToken token_;
  std::shared_ptr<Delivery> delivery_;
};

/// The signals and the run control of BackgroundRun<R> (Q_OBJECT cannot be a template).
class BackgroundRunBase : public QObject {
  Q_OBJECT
 public:
  explicit BackgroundRunBase(QObject* parent = nullptr);
  /// Cancels a running job and waits for it; no signal is emitted after this.
  ~BackgroundRunBase() override;

  /// From start() until the ending signal was emitted.
  bool isRunning() const { return running_; }
  /// Asks the job to stop (its observer returns Stop); the run then ends with cancelled().
  void cancel();
  /// Blocks until the job has returned and emits the ending signal now (not from the event loop).
  void waitForFinished();
  /// Blocks until the job's worker has returned, without any signal (destructors of the owner).
  void waitForWorker();

  /// Runs the job on the calling thread inside start() (tests): same signals, no event loop needed.
  void setSynchronous(bool synchronous) { synchronous_ = synchronous; }
  bool isSynchronous() const { return synchronous_; }
  /// The least time between two progress signals (ms; default 50); the first and a fraction of 1
  /// always pass.
  void setProgressInterval(int milliseconds) { progressIntervalMs_ = milliseconds; }

 signals:
  /// Progress in [0, 1] with the job's text (may be empty); on the GUI thread, in order.
  void progress(double fraction, const QString& text);
  /// The job returned; the result is ready for takeResult().
  void finished();
  /// The job returned after cancel() (its result, if any, is ready for takeResult()).
  void cancelled();
  /// The job threw; the message is the exception's what().
  void failed(const QString& message);

 protected:
  /// Runs body (which stores the result) and then, on this object's thread, store() and a signal.
  bool launch(std::function<void(RunObserver&)> body, std::function<void()> store);

 private:
  struct Outcome;
  void complete();

  QFutureWatcher<void>* watcher_ = nullptr;
  std::shared_ptr<RunObserver> observer_;
  std::shared_ptr<Outcome> outcome_;
  std::function<void()> store_;
  bool running_ = false;
  bool synchronous_ = false;
  int progressIntervalMs_ = 50;
};

/// A background run of `R job(RunObserver&)`; see the top of this file.
template <class R>
class BackgroundRun final : public BackgroundRunBase {
 public:
  using Job = std::function<R(RunObserver&)>;
  explicit BackgroundRun(QObject* parent = nullptr) : BackgroundRunBase(parent) {}

  /// Starts the job; false (and nothing happens) while a run is going on.
  bool start(Job job) {
    if (isRunning()) return false;
    result_.reset();
    auto slot = std::make_shared<std::optional<R>>();
    return launch([job = std::move(job), slot](RunObserver& observer) { slot->emplace(job(observer)); },
                  [this, slot] {
                    result_ = std::move(*slot);
                    slot->reset();
                  });
  }
  /// The last run's result, without taking it (nullptr when there is none).
  const R* result() const { return result_ ? &*result_ : nullptr; }
  /// Moves the last run's result out: it is delivered once, a second call gives nothing.
  std::optional<R> takeResult() { return std::exchange(result_, std::nullopt); }

 private:
  std::optional<R> result_;
};

}  // namespace metrofit
