/* view_report.h: X's figure: the charts on the screen redrawn as a report figure (one
 * panel each, stacked), from the values their strokes stand for. No curses here. */
#ifndef SPRINGSIM_VIEW_REPORT_H
#define SPRINGSIM_VIEW_REPORT_H

#include <stdio.h>

#include "report.h"
#include "view_picture.h"

/* Writes the n charts that have a report (fig_chart.report with a title) as one figure to
 * fp in format f, titled as look says (NULL: the panels' titles) with look's subtitle and
 * size. Returns 0, EDOM when no chart has a report, or an errno value. */
int fig_view_report(FILE *fp, enum fig_format f, const struct fig_chart *charts, int n,
                    const struct report_look *look);

#endif
