/* embed.c: a build step, not part of ptpgen: turns the files of templates/ into C strings.
 * Usage: embed templates/T/FILE... > templates.c; each is named by its path below templates/. */
#include <stdio.h>
#include <string.h>

int main(int argc, char **argv)
{
    int i, c;
    printf("/* Generated from templates/ by gen/embed/embed.c at build time: do not edit. */\n");
    printf("#include \"emit/template.h\"\n\nconst tpl_file tpl_files[] = {\n");
    for (i = 1; i < argc; i++) {
        const char *name = strncmp(argv[i], "templates/", 10) == 0 ? argv[i] + 10 : argv[i];
        FILE *f = fopen(argv[i], "rb");
        int col = 0;
        if (!f) {
            fprintf(stderr, "embed: cannot read %s\n", argv[i]);
            return 1;
        }
        printf("    {\"%s\",\n     \"", name);
        while ((c = getc(f)) != EOF) {
            if (c == '\n') {
                printf("\\n\"\n     \"");
                col = 0;
            } else if (c == '"' || c == '\\') {
                printf("\\%c", c);
            } else if (c == '?' && col > 0) {
                printf("\\?"); /* no trigraphs */
            } else if (c < 32 || c > 126) {
                printf("\\%03o", c);
            } else {
                putchar(c);
            }
            col++;
        }
        printf("\"},\n");
        fclose(f);
    }
    printf("};\n\nconst size_t tpl_count = %d;\n", argc - 1);
    return 0;
}
