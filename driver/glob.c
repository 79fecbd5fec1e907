/* File-system helpers of the batch driver (driver_records, driver_namelist_scan): POSIX
 * glob() for the patterns of `&records files`, and what a path names (a file, a
 * directory, nothing). Bound from Fortran with iso_c_binding (driver/records_group.f90,
 * driver/namelist_scan.f90); no state is kept here between calls but the handle the
 * caller holds. */
#include <glob.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Matches of one pattern, in byte order (strcmp: the same order in every locale), with
 * the directories left out. */
typedef struct {
    glob_t g;
    size_t n;        /* number of matches kept */
    char **paths;    /* the kept matches (pointers into g), sorted */
    size_t n_dirs;   /* directories matched and left out */
} sp_glob_t;

static int by_bytes(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Expand `pattern` (NUL-terminated). Returns a handle (NULL: out of memory) and
 * *status: 0 matches found or none (count 0), 1 a directory could not be read, 2 out of
 * memory. */
void *sp_glob_open(const char *pattern, int *status)
{
    sp_glob_t *h = calloc(1, sizeof *h);
    size_t i;
    int rc;
    *status = 0;
    if (h == NULL) {
        *status = 2;
        return NULL;
    }
    /* GLOB_MARK: a directory ends with '/', so that it can be left out */
    rc = glob(pattern, GLOB_MARK | GLOB_NOSORT, NULL, &h->g);
    if (rc == GLOB_NOMATCH) return h;
    if (rc != 0) {
        *status = rc == GLOB_NOSPACE ? 2 : 1;
        if (rc != GLOB_NOSPACE) return h;
        globfree(&h->g);
        free(h);
        return NULL;
    }
    h->paths = malloc((h->g.gl_pathc + 1) * sizeof *h->paths);
    if (h->paths == NULL) {
        *status = 2;
        globfree(&h->g);
        free(h);
        return NULL;
    }
    for (i = 0; i < h->g.gl_pathc; i++) {
        char *p = h->g.gl_pathv[i];
        size_t len = strlen(p);
        if (len > 0 && p[len - 1] == '/')
            h->n_dirs++;
        else
            h->paths[h->n++] = p;
    }
    qsort(h->paths, h->n, sizeof *h->paths, by_bytes);
    return h;
}

/* Number of matches kept (files), and of directories left out. */
void sp_glob_count(void *handle, int *n, int *n_dirs)
{
    sp_glob_t *h = handle;
    *n = h == NULL ? 0 : (int)h->n;
    *n_dirs = h == NULL ? 0 : (int)h->n_dirs;
}

/* Length of match i (1-based). */
int sp_glob_length(void *handle, int i)
{
    sp_glob_t *h = handle;
    return (int)strlen(h->paths[i - 1]);
}

/* Copy match i (1-based) into buf (buflen characters, no NUL added). */
void sp_glob_copy(void *handle, int i, char *buf, int buflen)
{
    sp_glob_t *h = handle;
    memcpy(buf, h->paths[i - 1], (size_t)buflen);
}

void sp_glob_close(void *handle)
{
    sp_glob_t *h = handle;
    if (h == NULL) return;
    if (h->paths != NULL) free(h->paths);
    globfree(&h->g);
    free(h);
}

/* What `path` names: 0 nothing (or it cannot be reached), 1 a regular file, 2 a
 * directory, 3 something else (a device, a FIFO, a socket). */
int sp_path_kind(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) return 0;
    if (S_ISREG(st.st_mode)) return 1;
    if (S_ISDIR(st.st_mode)) return 2;
    return 3;
}
