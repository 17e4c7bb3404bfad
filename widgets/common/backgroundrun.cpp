#include "widgets/common/backgroundrun.h"

#include <QFutureWatcher>
#include <QMetaObject>
#include <QPointer>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>

namespace metrofit {

/// Where a run's progress goes and how often; shared by the worker and the GUI thread.
struct RunObserver::Delivery {
  QPointer<BackgroundRunBase> target;
  bool synchronous = false;
  std::chrono::milliseconds interval{50};
  std::atomic<bool> active{true};  ///< false once the run ended: late progress is dropped
  std::mutex mutex;
  bool reported = false;
  double fraction = 0.0;
  std::chrono::steady_clock::time_point last;
};

/// What the worker leaves for the GUI thread besides the result.
struct BackgroundRunBase::Outcome {
  bool threw = false;
  QString error;
};

ObserverDecision RunObserver::onIteration(const IterationSummary& summary) {
  if (summary.progress >= 0.0) report(summary.progress);
  return token_.onIteration(summary);
}

void RunObserver::report(double fraction, const QString& text) {
  const std::shared_ptr<Delivery> d = delivery_;
  if (!d || !d->active.load()) return;
  double value = 0.0;
  {
    const std::lock_guard<std::mutex> lock(d->mutex);
    value = fraction < 0.0 ? d->fraction : std::min(1.0, fraction);
    const auto now = std::chrono::steady_clock::now();
    if (d->reported && value < 1.0 && now - d->last < d->interval) return;
    d->reported = true;
    d->fraction = value;
    d->last = now;
  }
  if (!d->target) return;
  if (d->synchronous) {
    emit d->target->progress(value, text);
    return;
  }
  QMetaObject::invokeMethod(
      d->target.data(),
      [d, value, text] {
        if (d->active.load() && d->target) emit d->target->progress(value, text);
      },
      Qt::QueuedConnection);
}

BackgroundRunBase::BackgroundRunBase(QObject* parent)
    : QObject(parent), watcher_(new QFutureWatcher<void>(this)) {
  connect(watcher_, &QFutureWatcher<void>::finished, this, &BackgroundRunBase::complete);
}

BackgroundRunBase::~BackgroundRunBase() {
  if (observer_) {
    observer_->token_.cancel();
    observer_->delivery_->active.store(false);
  }
  watcher_->disconnect(this);
  watcher_->waitForFinished();
}

void BackgroundRunBase::cancel() {
  if (running_ && observer_) observer_->token_.cancel();
}

void BackgroundRunBase::waitForFinished() {
  if (!running_) return;
  watcher_->waitForFinished();
  complete();
}

void BackgroundRunBase::waitForWorker() {
  watcher_->waitForFinished();
}

bool BackgroundRunBase::launch(std::function<void(RunObserver&)> body, std::function<void()> store) {
  if (running_) return false;
  auto observer = std::make_shared<RunObserver>();
  observer->delivery_ = std::make_shared<RunObserver::Delivery>();
  observer->delivery_->target = this;
  observer->delivery_->synchronous = synchronous_;
  observer->delivery_->interval = std::chrono::milliseconds(std::max(0, progressIntervalMs_));
  auto outcome = std::make_shared<Outcome>();
  observer_ = observer;
  outcome_ = outcome;
  store_ = std::move(store);
  running_ = true;
  auto work = [body = std::move(body), observer, outcome] {
    try {
      body(*observer);
    } catch (const std::exception& e) {
      outcome->threw = true;
      outcome->error = QString::fromUtf8(e.what());
    } catch (...) {
      outcome->threw = true;
      outcome->error = tr("unknown error");
    }
  };
  if (synchronous_) {
    work();
    complete();
  } else {
    watcher_->setFuture(QtConcurrent::run(std::move(work)));
  }
  return true;
}

void BackgroundRunBase::complete() {
  if (!running_ || !observer_) return;
  if (!observer_->delivery_->synchronous && !watcher_->isFinished()) return;
  running_ = false;
  observer_->delivery_->active.store(false);
  const bool wasCancelled = observer_->isCancelled();
  const std::shared_ptr<Outcome> outcome = std::exchange(outcome_, nullptr);
  std::function<void()> store = std::exchange(store_, nullptr);
  if (outcome->threw) {
    emit failed(outcome->error);
    return;
  }
  if (store) store();
  if (wasCancelled)
    emit cancelled();
  else
    emit finished();
}

}  // namespace metrofit
