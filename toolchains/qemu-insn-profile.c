// SPDX-License-Identifier: BSD-2-Clause
// A qemu-user TCG plugin that counts the guest instructions executed in each translated
// block and, when the program exits, writes one line "ADDRESS INSTRUCTIONS" per block
// start (hexadecimal guest address, decimal count) to the file named by its argument:
//   qemu-aarch64 -plugin ./insn-profile.so,out=FILE -L /usr/aarch64-linux-gnu PROGRAM ...
// bench/arm-kernel-shares.sh maps the addresses to functions. Declarations as in
// qemu-insn-count.c (Debian 12's qemu-user 7.2 ships no plugin header). Counts are not
// atomic: exact for single-threaded programs such as bench_detect with --threads 1.
#include <inttypes.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EXPORT __attribute__((visibility("default")))

typedef uint64_t qemu_plugin_id_t;
struct qemu_plugin_tb;
struct qemu_info;
enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };
typedef void (*tb_trans_fn)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);
typedef void (*udata_fn)(qemu_plugin_id_t id, void *userdata);

void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, tb_trans_fn cb);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
uint64_t qemu_plugin_tb_vaddr(const struct qemu_plugin_tb *tb);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb *tb, enum qemu_plugin_op op,
					      void *ptr, uint64_t imm);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, udata_fn cb, void *userdata);

EXPORT int qemu_plugin_version = 1;

// One counter per translation: a block translated again gets another (summed by address
// afterwards). Blocks are kept in chunks that never move, since the inline adds point
// into them.
struct block {
	uint64_t vaddr;
	uint64_t insns;
	uint64_t runs;
};
enum { kChunk = 65536 };
struct chunk {
	struct block blocks[kChunk];
	size_t used;
	struct chunk *next;
};
static struct chunk *chunks;
static char outPath[4096];

static void translated(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
	(void)id;
	if (!chunks || chunks->used == kChunk) {
		struct chunk *c = calloc(1, sizeof *c);
		if (!c)
			return; // out of memory: this block goes uncounted
		c->next = chunks;
		chunks = c;
	}
	struct block *b = &chunks->blocks[chunks->used++];
	b->vaddr = qemu_plugin_tb_vaddr(tb);
	b->insns = qemu_plugin_tb_n_insns(tb);
	qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &b->runs, 1);
}

static void finished(qemu_plugin_id_t id, void *userdata)
{
	(void)id;
	(void)userdata;
	FILE *f = fopen(outPath, "w");
	if (!f)
		return;
	for (struct chunk *c = chunks; c; c = c->next)
		for (size_t i = 0; i < c->used; i++)
			if (c->blocks[i].runs)
				fprintf(f, "%" PRIx64 " %" PRIu64 "\n", c->blocks[i].vaddr,
					c->blocks[i].insns * c->blocks[i].runs);
	fclose(f);
}

EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const struct qemu_info *info, int argc,
			       char **argv)
{
	(void)info;
	if (argc < 1 || strncmp(argv[0], "out=", 4) != 0) {
		fprintf(stderr, "insn-profile: needs out=FILE\n");
		return 1;
	}
	snprintf(outPath, sizeof outPath, "%s", argv[0] + 4);
	qemu_plugin_register_vcpu_tb_trans_cb(id, translated);
	qemu_plugin_register_atexit_cb(id, finished, NULL);
	return 0;
}
