/* embed.c: a build step, not part of ptpgen: turns the files of templates/ into C arrays.
 * Usage: embed templates/T/FILE... > templates.c; each is named by its path below templates/. */
#include <stdio.h>
#include <string.h>

/* Prints file path as the array tpl_text_<i> of its bytes and a final 0: an array, not a string
 * literal, so that ISO C's 4095-character limit on strings does not apply. Returns 0, or 1 if the
 * file cannot be read. */
static int put_text(int i, const char *path)
{
    FILE *f = fopen(path, "rb");
    int c, col = 0;
    if (!f) {
        fprintf(stderr, "embed: cannot read %s\n", path);
        return 1;
    }
    printf("static const char tpl_text_%d[] = {", i);
    while ((c = getc(f)) != EOF)
        printf("%s%d,", col++ % 16 ? " " : "\n    ", c);
    printf("%s0};\n", col % 16 ? " " : "\n    ");
    fclose(f);
    return 0;
}

int main(int argc, char **argv)
{
    int i;
    printf("/* Generated from templates/ by gen/embed/embed.c at build time: do not edit. */\n");
    printf("#include \"emit/template.h\"\n\n");
    for (i = 1; i < argc; i++)
        if (put_text(i, argv[i]))
            return 1;
    printf("\nconst tpl_file tpl_files[] = {\n");
    for (i = 1; i < argc; i++)
        printf("    {\"%s\", tpl_text_%d},\n",
               strncmp(argv[i], "templates/", 10) == 0 ? argv[i] + 10 : argv[i], i);
    printf("};\n\nconst size_t tpl_count = %d;\n", argc - 1);
    return 0;
}
