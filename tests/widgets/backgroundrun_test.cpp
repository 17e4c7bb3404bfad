// BackgroundRun<R> (widgets/common/backgroundrun.h), the one way the pages run a study off the GUI
// thread: progress arrives queued, in order and in [0, 1]; cancel() stops a long job and ends it with
// cancelled() rather than finished(); an exception becomes failed(message); the synchronous mode
// gives what the worker gives with the same signals; a result is delivered once. Offscreen.
#include <QSignalSpy>
#include <QTest>
#include <QThread>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "qtapp.h"
#include "widgets/common/backgroundrun.h"

namespace metrofit {
namespace {

using namespace std::chrono_literals;

/// A job of `steps` iterations that reports progress through the observer and stops when asked;
/// returns how many iterations it did.
long countingJob(RunObserver& observer, long steps, std::chrono::microseconds pause) {
  long done = 0;
  for (long i = 0; i < steps; ++i) {
    IterationSummary s;
    s.iteration = i;
    s.progress = static_cast<double>(i + 1) / static_cast<double>(steps);
    ++done;
    if (observer.onIteration(s) == ObserverDecision::Stop) break;
    std::this_thread::sleep_for(pause);
  }
  return done;
}

/// The names of the ending signals the run emitted, in order.
struct Endings {
  explicit Endings(BackgroundRunBase* run) {
    QObject::connect(run, &BackgroundRunBase::finished, [this] { names << "finished"; });
    QObject::connect(run, &BackgroundRunBase::cancelled, [this] { names << "cancelled"; });
    QObject::connect(run, &BackgroundRunBase::failed, [this](const QString& m) { names << "failed: " + m; });
  }
  QStringList names;
};

TEST(BackgroundRun, ProgressArrivesOnTheGuiThreadInOrderWithinZeroToOne) {
  BackgroundRun<long> run;
  run.setProgressInterval(0);  // every report passes, so the order is checked on all of them
  std::vector<double> fractions;
  bool onGuiThread = true;
  QObject::connect(&run, &BackgroundRunBase::progress, [&](double f, const QString&) {
    fractions.push_back(f);
    onGuiThread = onGuiThread && QThread::currentThread() == qApp->thread();
  });
  Endings endings(&run);
  ASSERT_TRUE(run.start([](RunObserver& o) {
    o.report(-1.0, QStringLiteral("starting"));  // unknown: keeps the last fraction (0)
    o.report(1.5);                               // clamped
    o.report(0.0);
    return countingJob(o, 200, 100us);
  }));
  EXPECT_TRUE(run.isRunning());
  QSignalSpy finished(&run, &BackgroundRunBase::finished);
  ASSERT_TRUE(finished.wait(10000));
  EXPECT_FALSE(run.isRunning());
  EXPECT_TRUE(onGuiThread);
  ASSERT_EQ(fractions.size(), 203u);
  EXPECT_EQ(fractions[0], 0.0);
  EXPECT_EQ(fractions[1], 1.0);
  EXPECT_EQ(fractions[2], 0.0);
  for (std::size_t i = 3; i < fractions.size(); ++i) {
    EXPECT_GE(fractions[i], 0.0);
    EXPECT_LE(fractions[i], 1.0);
    EXPECT_GT(fractions[i], fractions[i - 1]) << i;  // the worker's order
  }
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_EQ(endings.names, QStringList{"finished"});
  ASSERT_TRUE(run.result());
  EXPECT_EQ(*run.result(), 200);
}

TEST(BackgroundRun, ProgressIsThrottledButTheLastFractionPasses) {
  BackgroundRun<long> run;
  run.setProgressInterval(60000);  // nothing between the first report and fraction 1
  std::vector<double> fractions;
  QObject::connect(&run, &BackgroundRunBase::progress,
                   [&](double f, const QString&) { fractions.push_back(f); });
  QSignalSpy finished(&run, &BackgroundRunBase::finished);
  ASSERT_TRUE(run.start([](RunObserver& o) { return countingJob(o, 500, 0us); }));
  ASSERT_TRUE(finished.wait(10000));
  EXPECT_EQ(fractions, (std::vector<double>{1.0 / 500.0, 1.0}));
}

TEST(BackgroundRun, CancelStopsALongJobAndEndsWithCancelledNotFinished) {
  BackgroundRun<long> run;
  Endings endings(&run);
  QSignalSpy cancelled(&run, &BackgroundRunBase::cancelled);
  // 100000 iterations of 1 ms: far more than the test waits for.
  ASSERT_TRUE(run.start([](RunObserver& o) { return countingJob(o, 100000, 1ms); }));
  QSignalSpy progress(&run, &BackgroundRunBase::progress);
  ASSERT_TRUE(progress.wait(10000));  // it is running
  const auto started = std::chrono::steady_clock::now();
  run.cancel();
  ASSERT_TRUE(cancelled.wait(10000));
  EXPECT_LT(std::chrono::steady_clock::now() - started, 5s);
  QTest::qWait(50);  // nothing else comes
  EXPECT_EQ(endings.names, QStringList{"cancelled"});
  EXPECT_FALSE(run.isRunning());
  // What the job returned after the stop (a method's best so far) is still the result.
  const std::optional<long> done = run.takeResult();
  ASSERT_TRUE(done);
  EXPECT_LT(*done, 100000);
}

TEST(BackgroundRun, AnExceptionBecomesFailedWithItsMessage) {
  BackgroundRun<int> run;
  Endings endings(&run);
  QSignalSpy failed(&run, &BackgroundRunBase::failed);
  ASSERT_TRUE(run.start([](RunObserver&) -> int { throw std::runtime_error("the column 'T9' is missing"); }));
  ASSERT_TRUE(failed.wait(10000));
  EXPECT_EQ(failed.at(0).at(0).toString(), QStringLiteral("the column 'T9' is missing"));
  EXPECT_EQ(endings.names, QStringList{"failed: the column 'T9' is missing"});
  EXPECT_FALSE(run.result());
  EXPECT_FALSE(run.isRunning());

  BackgroundRun<int> sync;
  sync.setSynchronous(true);
  Endings syncEndings(&sync);
  ASSERT_TRUE(sync.start([](RunObserver&) -> int { throw std::invalid_argument("bad seed"); }));
  EXPECT_EQ(syncEndings.names, QStringList{"failed: bad seed"});
}

TEST(BackgroundRun, SynchronousModeGivesTheAsynchronousResultAndSignals) {
  const auto job = [](RunObserver& o) {
    double sum = 0.0;
    for (int i = 1; i <= 50; ++i) {
      sum += 1.0 / i;
      o.report(i / 50.0, QString::number(i));
    }
    return sum;
  };
  BackgroundRun<double> async;
  async.setProgressInterval(0);
  QStringList asyncTexts;
  QObject::connect(&async, &BackgroundRunBase::progress, [&](double, const QString& t) { asyncTexts << t; });
  Endings asyncEndings(&async);
  QSignalSpy finished(&async, &BackgroundRunBase::finished);
  ASSERT_TRUE(async.start(job));
  ASSERT_TRUE(finished.wait(10000));

  BackgroundRun<double> sync;
  sync.setSynchronous(true);
  sync.setProgressInterval(0);
  QStringList syncTexts;
  QObject::connect(&sync, &BackgroundRunBase::progress, [&](double, const QString& t) { syncTexts << t; });
  Endings syncEndings(&sync);
  ASSERT_TRUE(sync.start(job));
  // Everything happened inside start(): no event loop was needed.
  EXPECT_FALSE(sync.isRunning());
  EXPECT_EQ(syncEndings.names, QStringList{"finished"});
  EXPECT_EQ(asyncEndings.names, QStringList{"finished"});
  EXPECT_EQ(syncTexts, asyncTexts);
  EXPECT_EQ(syncTexts.size(), 50);
  const std::optional<double> a = async.takeResult();
  const std::optional<double> s = sync.takeResult();
  ASSERT_TRUE(a && s);
  EXPECT_EQ(*a, *s);
}

TEST(BackgroundRun, TheResultIsDeliveredOnceAndAStartWhileRunningIsRefused) {
  BackgroundRun<std::string> run;
  Endings endings(&run);
  QSignalSpy finished(&run, &BackgroundRunBase::finished);
  ASSERT_TRUE(run.start([](RunObserver& o) {
    while (!o.isCancelled()) std::this_thread::sleep_for(1ms);
    return std::string("first");
  }));
  EXPECT_FALSE(run.start([](RunObserver&) { return std::string("second"); }));
  run.cancel();
  QSignalSpy cancelled(&run, &BackgroundRunBase::cancelled);
  ASSERT_TRUE(cancelled.wait(10000));
  EXPECT_EQ(run.takeResult(), std::optional<std::string>("first"));
  EXPECT_EQ(run.takeResult(), std::nullopt);

  ASSERT_TRUE(run.start([](RunObserver&) { return std::string("third"); }));
  ASSERT_TRUE(finished.wait(10000));
  QTest::qWait(50);
  EXPECT_EQ(finished.size(), 1);
  EXPECT_EQ(endings.names, (QStringList{"cancelled", "finished"}));
  EXPECT_EQ(run.takeResult(), std::optional<std::string>("third"));
  EXPECT_EQ(run.takeResult(), std::nullopt);
}

TEST(BackgroundRun, DestroyingARunningRunCancelsAndWaitsWithoutSignals) {
  std::atomic<bool> stopped{false};
  int endings = 0;
  {
    BackgroundRun<int> run;
    QObject::connect(&run, &BackgroundRunBase::finished, [&] { ++endings; });
    QObject::connect(&run, &BackgroundRunBase::cancelled, [&] { ++endings; });
    ASSERT_TRUE(run.start([&stopped](RunObserver& o) {
      while (!o.isCancelled()) std::this_thread::sleep_for(1ms);
      stopped = true;
      return 1;
    }));
  }
  EXPECT_TRUE(stopped.load());
  QTest::qWait(20);
  EXPECT_EQ(endings, 0);
}

}  // namespace
}  // namespace metrofit
