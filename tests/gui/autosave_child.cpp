// Helper process of autosave_test: opens the project given as argv[1], then edits its name
// ("edit <n>", n = 0, 1, 2, ...) and autosaves after each edit, printing "autosaved <n>" once the
// side file holds edit n, until it is killed. It never saves the project itself.
#include <QCoreApplication>
#include <QThread>
#include <cstdio>
#include <exception>

#include "app/gui/autosave.h"
#include "widgets/document/projectdocument.h"

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  if (argc != 2) {
    std::fprintf(stderr, "usage: autosave_child PROJECT\n");
    return 2;
  }
  try {
    metrofit::ProjectDocument doc;
    metrofit::Autosave autosave(&doc);
    autosave.setIntervalMs(0);
    autosave.setDecider([](const metrofit::RecoveryOffer&) { return metrofit::RecoveryChoice::Discard; });
    autosave.open(QString::fromLocal8Bit(argv[1]));
    doc.setValue(metrofit::ProjectField::description(), QStringLiteral("autosave child"));
    for (int n = 0;; ++n) {
      doc.endEditSequence();
      doc.setValue(metrofit::ProjectField::name(), QStringLiteral("edit %1").arg(n));
      if (!autosave.tick()) {
        std::fprintf(stderr, "autosave_child: tick wrote nothing\n");
        return 1;
      }
      autosave.waitForWrite();
      std::printf("autosaved %d\n", n);
      std::fflush(stdout);
      QThread::usleep(500);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "autosave_child: %s\n", e.what());
    return 1;
  }
}
