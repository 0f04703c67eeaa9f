// The plugin's menu icons: every ShowInMenu hint names an icon, each icon is in the plugin's Qt
// resources, is a valid SVG, draws something, and differs from every other; writes them side by side.
#include <QDir>
#include <QFile>
#include <QGuiApplication>
#include <QImage>
#include <QPainter>
#include <QRegularExpression>
#include <QSvgRenderer>
#include <QTextStream>

#include <cstdio>
#include <map>

namespace
{
constexpr int IconSize = 64;

/// The icon path of every proxy with a ShowInMenu hint in the XML files of `directory`:
/// proxy name -> icon ("" when the hint names none).
std::map<QString, QString> MenuIcons(const QDir& directory)
{
  std::map<QString, QString> icons;
  const QRegularExpression proxy(QStringLiteral("<(?:Source|Writer)Proxy name=\"([^\"]+)\""));
  const QRegularExpression menu(QStringLiteral("<ShowInMenu category=\"Kerf\"(?: icon=\"([^\"]*)\")?"));
  for (const QString& name : directory.entryList({ QStringLiteral("*.xml") }, QDir::Files, QDir::Name))
  {
    QFile file(directory.filePath(name));
    if (!file.open(QIODevice::ReadOnly))
    {
      std::printf("ERROR: cannot read %s\n", qPrintable(file.fileName()));
      continue;
    }
    const QString text = QTextStream(&file).readAll();
    QString current;
    int position = 0;
    for (;;)
    {
      const QRegularExpressionMatch nextProxy = proxy.match(text, position);
      const QRegularExpressionMatch nextMenu = menu.match(text, position);
      if (!nextMenu.hasMatch())
      {
        break;
      }
      if (nextProxy.hasMatch() && nextProxy.capturedStart() < nextMenu.capturedStart())
      {
        current = nextProxy.captured(1);
        position = nextProxy.capturedEnd();
        continue;
      }
      icons[current] = nextMenu.captured(1);
      position = nextMenu.capturedEnd();
    }
  }
  return icons;
}

/// The share of the icon's pixels that are not transparent.
double Coverage(const QImage& image)
{
  int drawn = 0;
  for (int y = 0; y < image.height(); ++y)
  {
    for (int x = 0; x < image.width(); ++x)
    {
      drawn += qAlpha(image.pixel(x, y)) > 0;
    }
  }
  return static_cast<double>(drawn) / (image.width() * image.height());
}
} // namespace

int main(int argc, char* argv[])
{
  QGuiApplication application(argc, argv);
  if (argc != 3)
  {
    std::printf("ERROR: usage: TestMenuIcons <plugin XML directory> <output PNG>\n");
    return 1;
  }
  Q_INIT_RESOURCE(KerfIcons);
  const std::map<QString, QString> icons = MenuIcons(QDir(QString::fromLocal8Bit(argv[1])));
  bool ok = icons.size() >= 20;
  if (!ok)
  {
    std::printf("ERROR: %zu menu entries found, expected at least 20\n", icons.size());
  }
  QImage gallery(IconSize * static_cast<int>(icons.size()), IconSize, QImage::Format_ARGB32);
  gallery.fill(Qt::white);
  QPainter galleryPainter(&gallery);
  std::map<QByteArray, QString> drawings;
  int column = 0;
  for (const auto& [proxy, icon] : icons)
  {
    const QString expected = QStringLiteral(":/Kerf/Icons/") + QString(proxy).remove(0, 4) + QStringLiteral(".svg");
    QSvgRenderer renderer(icon);
    QImage image(IconSize, IconSize, QImage::Format_ARGB32);
    image.fill(Qt::transparent);
    QPainter painter(&image);
    renderer.render(&painter);
    painter.end();
    const double coverage = Coverage(image);
    const QByteArray pixels(reinterpret_cast<const char*>(image.constBits()), static_cast<int>(image.sizeInBytes()));
    std::printf("%-36s %-48s coverage %.2f\n", qPrintable(proxy), qPrintable(icon), coverage);
    if (icon != expected || !QFile::exists(icon) || !renderer.isValid() || coverage < 0.3 || drawings.count(pixels))
    {
      std::printf("ERROR: %s: icon \"%s\" (expected %s, in the resources: %d, valid SVG: %d, coverage %.2f, same "
                  "drawing as %s)\n",
        qPrintable(proxy), qPrintable(icon), qPrintable(expected), QFile::exists(icon), renderer.isValid(), coverage,
        drawings.count(pixels) ? qPrintable(drawings[pixels]) : "none");
      ok = false;
    }
    drawings[pixels] = proxy;
    galleryPainter.drawImage(IconSize * column++, 0, image);
  }
  galleryPainter.end();
  if (!gallery.save(QString::fromLocal8Bit(argv[2])))
  {
    std::printf("ERROR: cannot write %s\n", argv[2]);
    ok = false;
  }
  return ok ? 0 : 1;
}
