#pragma once
// Private to the hammer-station page (hammer_station_page.cpp,
// hammer_station_events.cpp). Not included elsewhere.

#include <qwt_plot.h>
#include <qwt_text.h>
#include <QFont>
#include <QString>

namespace mozzi::views::hammer_station {

// Axis titles in the page's normal font (Qwt's default is large and bold:
// too big for the traces at 1280x800).
inline void setAxisText(QwtPlot* plot, int axis, const QString& text) {
  QwtText title(text);
  // On one line: wrapped at a word break, a unit splits ("Response [m/" over "s^2]").
  title.setRenderFlags(Qt::AlignCenter);
  QFont f = plot->font();
  f.setBold(false);
  title.setFont(f);
  plot->setAxisTitle(axis, title);
}

}  // namespace mozzi::views::hammer_station
