/* test_targets.c: the target registry (gen/emit/targets.c): unique names and suffixes, an
 * emitter each, lookup that round-trips, and a --list-targets line per target. */
#include "check.h"
#include "emit/targets.h"
#include "plan/sched.h"

#include <string.h>

/* Every entry has a name, a description and either an emitter or a GPU kernel table; no name or
 * file suffix repeats. */
static void check_entries(void)
{
    int i, k, bad = -1;
    for (i = 0; i < tgt_count && bad < 0; i++) {
        const tgt_target *g = &tgt_targets[i];
        if (!g->name || !g->name[0] || !g->suffix || !g->description || !g->emit == !g->gpu ||
            g->options >> TGT_NOPTIONS)
            bad = i;
        for (k = 0; k < i && bad < 0; k++)
            if (strcmp(g->name, tgt_targets[k].name) == 0 ||
                (g->suffix[0] && strcmp(g->suffix, tgt_targets[k].suffix) == 0))
                bad = i;
    }
    check(tgt_count >= 8 && bad < 0,
          "every target has a unique name and suffix, an emitter, a description, known option bits",
          "entry %d (%s)", bad, bad >= 0 ? tgt_targets[bad].name : "");
}

/* tgt_find returns each entry by its name, and NULL for names that are none. */
static void check_lookup(void)
{
    int i, ok = 1;
    for (i = 0; i < tgt_count; i++)
        ok &= tgt_find(tgt_targets[i].name) == &tgt_targets[i];
    ok &= !tgt_find("") && !tgt_find("glsx") && !tgt_find("GLSL") && !tgt_find("json ");
    check(ok, "tgt_find round-trips every name and finds no other", "");
}

/* tgt_write_list writes one line per target, starting "name suffix options", every option name
 * once per bit. */
static void check_list(void)
{
    sbuf b;
    const char *p;
    int i, k, ok = 1;
    sbuf_init(&b);
    tgt_write_list(&b);
    p = b.s;
    for (i = 0; i < tgt_count && ok; i++) {
        const tgt_target *g = &tgt_targets[i];
        char want[256];
        int n = snprintf(want, sizeof want, "%s %s ", g->name, g->suffix[0] ? g->suffix : "-");
        for (k = 0; k < TGT_NOPTIONS; k++)
            if (g->options >> k & 1)
                n += snprintf(want + n, sizeof want - (size_t)n, "%s%s",
                              want[n - 1] == ' ' ? "" : ",", tgt_option_name(k));
        snprintf(want + n, sizeof want - (size_t)n, "%s %s\n", g->options ? "" : "-",
                 g->description);
        ok = strncmp(p, want, strlen(want)) == 0;
        p += ok ? strlen(want) : 0;
    }
    check(ok && *p == '\0',
          "--list-targets has one 'name suffix options description' line per target",
          "at target %d: '%.60s'", i - 1, p);
    sbuf_clear(&b);
}

/* Every target whose output opens with a comment (all with a file suffix but json) names there
 * the file the registry's suffix gives: "/\* cull_1x2.comp: " for --prefix cull_1x2_. */
static void check_banner_names(void)
{
    tp_table t;
    sched s;
    ptp_error err;
    out_info info = {0};
    int i, named = 0, bad = -1;
    if (!check(!tp_derive(&t, 1, 2, &err) && !sched_build(&s, &t, 4, 8, &err), "derive 1x2",
               "%s", err.msg))
        return;
    info.command = "test";
    info.prefix = "cull_1x2_";
    info.sched = &s;
    for (i = 0; i < tgt_count && bad < 0; i++) {
        const tgt_target *g = &tgt_targets[i];
        char want[64];
        sbuf b;
        sbuf_init(&b);
        snprintf(want, sizeof want, "/* cull_1x2%s: ", g->suffix);
        if (tgt_emit_target(&b, g, &t, &info, &err) || !b.s)
            bad = i;
        else if (g->suffix[0] && b.s[0] == '/')
            named += strncmp(b.s, want, strlen(want)) == 0 ? 1 : (bad = i, 0);
        sbuf_clear(&b);
    }
    check(bad < 0 && named == tgt_count - 2,
          "every target's banner names its file by the registry's suffix (all but json and stats)",
          "%d named; entry %d (%s)", named, bad, bad >= 0 ? tgt_targets[bad].name : "");
    sched_clear(&s);
    tp_clear(&t);
}

int main(void)
{
    check_entries();
    check_lookup();
    check_list();
    check_banner_names();
    return check_exit();
}
