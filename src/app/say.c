/* say.c: the status message, the one line every part of the app says what happened on. */
#include "app.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

unsigned app_say(struct app *app, bool error, const char *fmt, ...)
{
    char line[sizeof app->message];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    /* Whatever went into it, the status line gets no control byte. */
    config_escape(line, strlen(line), sizeof line, app->message, sizeof app->message);
    app->message_is_error = error;
    return APP_CHANGED_MESSAGE;
}
