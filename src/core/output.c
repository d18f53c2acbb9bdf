/* output.c: atomic output files and the headless CSV. */
#include "output.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The named temporary file being written, for output_discard_pending: a copy in static
 * storage a signal handler may read, valid while pending_set is 1. */
static char pending_path[PATH_MAX + 16];
static volatile sig_atomic_t pending_set;

/* Records tmp as the temporary file a signal handler must remove. */
static void pending_begin(const char *tmp)
{
    pending_set = 0;
    size_t n = strlen(tmp);
    if (n < sizeof pending_path) {
        memcpy(pending_path, tmp, n + 1);
        atomic_signal_fence(memory_order_seq_cst); /* the name before the flag */
        pending_set = 1;
    }
}

void output_discard_pending(void)
{
    if (pending_set) {
        pending_set = 0;
        unlink(pending_path);
    }
}

/* Frees the names of o. */
static void forget(struct output *o)
{
    pending_set = 0;
    free(o->path);
    free(o->tmp);
    o->path = o->tmp = NULL;
}

/* The file a chain of symbolic links ends at, even when it does not exist yet (a
 * dangling link is written through, creating its target): a malloc'ed path, or NULL
 * with errno set (ELOOP for a loop or a chain over 40 links). */
static char *link_target(const char *path)
{
    char *cur = strdup(path);
    for (int hops = 0; cur && hops < 40; hops++) {
        struct stat lst;
        if (lstat(cur, &lst) != 0 || !S_ISLNK(lst.st_mode))
            return cur; /* the end of the chain, there or not */
        char to[PATH_MAX];
        ssize_t n = readlink(cur, to, sizeof to - 1);
        if (n < 0) {
            free(cur);
            return NULL;
        }
        to[n] = '\0';
        /* A relative target is relative to the link's directory. */
        const char *slash = strrchr(cur, '/');
        int dir = to[0] == '/' || !slash ? 0 : (int)(slash - cur) + 1;
        size_t len = (size_t)dir + (size_t)n + 1;
        char *next = malloc(len);
        if (!next) {
            free(cur);
            return NULL;
        }
        snprintf(next, len, "%.*s%s", dir, cur, to);
        free(cur);
        cur = next;
    }
    if (cur) {
        free(cur);
        errno = ELOOP;
    }
    return NULL;
}

/* Gives the file being written the owner and group of the one it replaces, where the
 * user may (root always; others their own groups: EPERM leaves it theirs, as a plain
 * creat() would), then its mode, which a change of owner may have cleared bits of. */
static void keep_owner(int fd, const struct output *o, mode_t mode)
{
    if (o->owner != (uid_t)-1 && fchown(fd, o->owner, o->group) != 0)
        (void)(fchown(fd, (uid_t)-1, o->group) == 0);
    fchmod(fd, mode);
}

/* An unnamed file in path's directory (Linux O_TMPFILE), or -1. */
static int open_unnamed(const char *path, mode_t mode)
{
#ifdef O_TMPFILE
    char dir[4096];
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, sizeof dir, ".");
    else if (slash == path)
        snprintf(dir, sizeof dir, "/");
    else
        snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
    return open(dir, O_TMPFILE | O_WRONLY | O_CLOEXEC, mode);
#else
    (void)path, (void)mode;
    errno = EOPNOTSUPP;
    return -1;
#endif
}

int output_open(struct output *o, const char *path)
{
    struct stat st;
    memset(o, 0, sizeof *o);
    if (!path || strcmp(path, "-") == 0) {
        o->fp = stdout;
        return 0;
    }
    bool exists = stat(path, &st) == 0;
    if (!exists && errno != ENOENT)
        return errno; /* a symbolic link loop, a path through a file, ... */
    if (exists && !S_ISREG(st.st_mode)) {
        if (S_ISDIR(st.st_mode))
            return EISDIR;
        o->fp = fopen(path, "w");
        return o->fp ? 0 : errno;
    }
    /* The new file gets the old one's mode, owner and group (root writing over a user's
     * file leaves it theirs), or what a plain creat() would give. */
    mode_t mask = umask(0);
    umask(mask);
    mode_t mode = exists ? st.st_mode & 07777 : 0666 & ~mask;
    o->owner = exists ? st.st_uid : (uid_t)-1;
    o->group = exists ? st.st_gid : (gid_t)-1;
    /* Through a symbolic link: replace (or create) the file it points to, not the link. */
    o->path = link_target(path);
    if (!o->path)
        return errno;
    path = o->path;
    size_t n = strlen(path);
    o->tmp = malloc(n + 16);
    if (!o->tmp) {
        forget(o);
        return ENOMEM;
    }
    /* NAME.tmp-XXXXXX beside the target; a short name in its directory instead when that
     * would be past the longest name a directory holds (a target of 245-255 bytes). */
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    if (strlen(base) + strlen(".tmp-XXXXXX") <= NAME_MAX)
        snprintf(o->tmp, n + 16, "%s.tmp-XXXXXX", path);
    else
        snprintf(o->tmp, n + 16, "%.*s.ss.tmp-XXXXXX", (int)(base - path), path);
    int fd = open_unnamed(path, mode);
    if (fd >= 0) {
        o->unnamed = true;
        keep_owner(fd, o, mode);
    } else if (errno == ENOENT || errno == ENOTDIR || errno == EACCES || errno == EROFS) {
        int e = errno;
        forget(o);
        return e;
    } else {
        /* A file system without O_TMPFILE: a named temporary file, removed by
         * output_discard_pending if a signal ends the program first. */
        sigset_t all, old;
        sigfillset(&all);
        sigprocmask(SIG_BLOCK, &all, &old);
        fd = mkstemp(o->tmp);
        if (fd >= 0)
            pending_begin(o->tmp);
        sigprocmask(SIG_SETMASK, &old, NULL);
        if (fd < 0) {
            int e = errno;
            forget(o);
            return e;
        }
        keep_owner(fd, o, mode);
    }
    o->fp = fdopen(fd, "w");
    if (!o->fp) {
        int e = errno;
        close(fd);
        if (!o->unnamed)
            unlink(o->tmp);
        forget(o);
        return e;
    }
    return 0;
}

/* Gives the complete unnamed file a temporary name beside the target. */
static int name_unnamed(struct output *o)
{
    char proc[64];
    snprintf(proc, sizeof proc, "/proc/self/fd/%d", fileno(o->fp));
    size_t n = strlen(o->tmp);
    for (int attempt = 0; attempt < 100; attempt++) {
        /* A fresh suffix each time: the XXXXXX of the template, made unique by hand. */
        snprintf(o->tmp + n - 6, 7, "%06x", (unsigned)(getpid() * 7919 + attempt * 104729) &
                                                0xffffffu);
        pending_begin(o->tmp); /* from the moment it may have a name */
        if (linkat(AT_FDCWD, proc, AT_FDCWD, o->tmp, AT_SYMLINK_FOLLOW) == 0)
            return 0;
        pending_set = 0;
        if (errno != EEXIST)
            return errno;
    }
    return EEXIST;
}

int output_link_new(struct output *o, const char *path)
{
    if (!o->fp || !o->tmp)
        return EINVAL; /* standard output, or a device written in place */
    if (fflush(o->fp) != 0 || ferror(o->fp))
        return errno ? errno : EIO;
    if (fsync(fileno(o->fp)) != 0)
        return errno;
    if (o->unnamed) {
        char proc[64];
        snprintf(proc, sizeof proc, "/proc/self/fd/%d", fileno(o->fp));
        if (linkat(AT_FDCWD, proc, AT_FDCWD, path, AT_SYMLINK_FOLLOW) != 0)
            return errno;
    } else if (link(o->tmp, path) != 0) {
        return errno;
    }
    return 0;
}

int output_close(struct output *o, bool commit)
{
    int err = 0;
    if (!o->fp)
        return 0;
    if (fflush(o->fp) != 0 || ferror(o->fp))
        err = errno ? errno : EIO;
    if (o->fp == stdout) {
        o->fp = NULL;
        return err;
    }
    bool named = !o->unnamed;
    if (o->tmp && !err && commit && fsync(fileno(o->fp)) != 0)
        err = errno;
    if (o->tmp && !err && commit && o->unnamed) {
        err = name_unnamed(o);
        named = err == 0;
    }
    if (fclose(o->fp) != 0 && !err)
        err = errno;
    o->fp = NULL;
    if (o->tmp) {
        if (!err && commit && rename(o->tmp, o->path) != 0)
            err = errno;
        pending_set = 0; /* renamed, or removed just below */
        if (named && (err || !commit))
            unlink(o->tmp);
        forget(o);
    }
    return err;
}

void output_csv_header(FILE *fp, int n, bool energy)
{
    static const char *const groups[] = {"x", "v", "a"};
    fputc('t', fp);
    for (int g = 0; g < 3; g++)
        for (int i = 1; i <= n; i++)
            fprintf(fp, ",%s%d", groups[g], i);
    fputs(",motor", fp);
    if (energy)
        fputs(",kinetic,potential,dissipated,motor_work,contact,force_work", fp);
    fputc('\n', fp);
}

void output_csv_values(FILE *fp, int n, double t, const double *x, const double *v,
                       const double *a, double u, const double *energy)
{
    fprintf(fp, "%.12g", t);
    for (int i = 0; i < n; i++)
        fprintf(fp, ",%.12g", x[i]);
    for (int i = 0; i < n; i++)
        fprintf(fp, ",%.12g", v[i]);
    for (int i = 0; i < n; i++)
        fprintf(fp, ",%.12g", a[i]);
    fprintf(fp, ",%.12g", u);
    if (energy)
        fprintf(fp, ",%.12g,%.12g,%.12g,%.12g,%.12g,%.12g", energy[0], energy[1], energy[2],
                energy[3], energy[4], energy[5]);
    fputc('\n', fp);
}

/* Whether all n values at v are finite. */
static bool all_finite(const double *v, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(v[i]))
            return false;
    return true;
}

/* The row's values for the current state of s: accelerations into scratch, the energy
 * books into books (if energy). Returns whether every one is finite. */
static bool row_values(const struct sim *s, bool energy, double *scratch, double *books)
{
    struct energy e;
    int n = sim_model(s)->n;
    sim_accel(s, scratch);
    if (energy) {
        sim_energy(s, &e);
        books[0] = e.kinetic, books[1] = e.potential, books[2] = e.dissipated;
        books[3] = e.motor_work, books[4] = e.contact, books[5] = e.force_work;
    }
    return all_finite(sim_x(s), n) && all_finite(sim_v(s), n) && all_finite(scratch, n) &&
           (!energy || all_finite(books, 6)) && isfinite(sim_end_position(s));
}

bool output_state_finite(const struct sim *s, double *scratch)
{
    double books[6];
    return row_values(s, true, scratch, books);
}

int output_csv_row(FILE *fp, const struct sim *s, bool energy, double *scratch)
{
    double books[6];
    if (!row_values(s, energy, scratch, books))
        return -1;
    output_csv_values(fp, sim_model(s)->n, sim_time(s), sim_x(s), sim_v(s), scratch,
                      sim_end_position(s), energy ? books : NULL);
    return 0;
}
