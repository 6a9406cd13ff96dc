#include "core/raster/svg_to_png.h"

#include <QBuffer>
#include <QByteArray>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QSvgRenderer>

#include <cstdlib>
#include <mutex>
#include <stdexcept>

#include "core/io/atomic_file.h"

namespace autoblock {
namespace {

// Qt's chatter (e.g. about XDG_RUNTIME_DIR) is not ours to print; real failures surface as errors.
void quiet(QtMsgType, const QMessageLogContext&, const QString&) {}

// Text needs a QGuiApplication; outside one (the CLI), make an offscreen one once. It is never
// destroyed: tearing it down during static destruction at exit would race Qt's own globals.
void ensure_gui_application() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (QCoreApplication::instance()) return;
    setenv("QT_QPA_PLATFORM", "offscreen", 0);
    qInstallMessageHandler(quiet);
    static int argc = 1;
    static char name[] = "autoblock";
    static char* argv[] = {name, nullptr};
    new QGuiApplication(argc, argv);  // NOLINT: deliberately leaked, see above
  });
}

}  // namespace

void write_png_from_svg(const std::string& svg, const std::string& path, int width) {
  ensure_gui_application();
  QSvgRenderer renderer(QByteArray(svg.data(), static_cast<int>(svg.size())));
  if (!renderer.isValid()) throw std::runtime_error("the picture's SVG could not be rendered");
  const QSize size = renderer.defaultSize();
  const int height = std::max(1, static_cast<int>(static_cast<double>(width) * size.height() / std::max(1, size.width())));
  QImage image(width, height, QImage::Format_ARGB32);
  image.fill(Qt::white);
  {
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    renderer.render(&painter);
  }
  write_file_atomically(path, [&](const std::string& temporary) {
    return image.save(QString::fromStdString(temporary), "PNG");
  });
}

}  // namespace autoblock

// The entry point libautoblock_raster.so exports for write_picture (picture_file.h), which loads it
// on first use.
extern "C" __attribute__((visibility("default"))) void autoblock_write_png_from_svg(const std::string& svg,
                                                                                   const std::string& path,
                                                                                   int width) {
  autoblock::write_png_from_svg(svg, path, width);
}
