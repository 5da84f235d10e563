/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_dl_internal.h - libzip, libxml2 and libyaml, loaded when a zip
 * container (x3p, Excel workbook, contact.engineering) is first read or an x3p
 * written, not when a program starts.
 *
 * Linked, they and what they pull in (libcrypto, ICU, libstdc++, liblzma,
 * libbz2) were 13.5 of the 21 ms of CPU a tool's start took (perf stat,
 * an empty main linked with and without them, 2-core machine), paid twice
 * by a tool that restarts for passive waiting (threads.h) and by every
 * run of a pipeline that never opens a zip.
 *
 * The readers and the x3p writer call these libraries by their own names:
 * included after every other header, this file turns each name into the
 * function pointer the library exported (the functions are listed here;
 * one missing from the lists is an undefined reference when linking).
 * Before its first call a reader calls rc__dl_zip, rc__dl_xml or
 * rc__dl_yaml: 0 when the library is loaded (once a process; never
 * unloaded, like a linked one), else -1 with an error naming the Debian
 * package to install.  The pointer tables are the process's, written
 * once under a lock, like the dynamic linker's own table for a linked
 * library: they hold no state of a computation.
 */
#ifndef RC_IO_DL_INTERNAL_H
#define RC_IO_DL_INTERNAL_H

#include "rc_err.h"

#include <libxml/globals.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <libxml/xmlreader.h>
#include <yaml.h>
#include <zip.h>

#define RC_DL_ZIP_FUNCS(X) \
	X(zip_close) X(zip_discard) X(zip_error_fini) X(zip_error_init) \
	X(zip_error_strerror) X(zip_fclose) X(zip_file_add) X(zip_fopen) \
	X(zip_fread) X(zip_name_locate) X(zip_open_from_source) \
	X(zip_set_file_compression) X(zip_source_buffer) \
	X(zip_source_buffer_create) X(zip_source_close) X(zip_source_error) \
	X(zip_source_free) X(zip_source_keep) X(zip_source_open) \
	X(zip_source_read) X(zip_stat) X(zip_strerror)
/* xmlFree is a variable of libxml2 (a function pointer), not a function */
#define RC_DL_XML_FUNCS(X) \
	X(xmlAddChild) X(xmlDocDumpFormatMemoryEnc) X(xmlDocGetRootElement) \
	X(xmlDocSetRootElement) X(xmlFreeDoc) X(xmlFreeTextReader) \
	X(xmlGetNsProp) X(xmlGetProp) X(xmlNewDoc) X(xmlNewDocRawNode) \
	X(xmlNewNode) X(xmlNewNs) X(xmlNodeGetContent) X(xmlReadMemory) \
	X(xmlReaderForMemory) X(xmlSetNs) X(xmlSetProp) \
	X(xmlTextReaderConstLocalName) X(xmlTextReaderExpand) \
	X(xmlTextReaderNext) X(xmlTextReaderNodeType) X(xmlTextReaderRead) \
	X(xmlFree)
#define RC_DL_YAML_FUNCS(X) \
	X(yaml_document_delete) X(yaml_document_get_node) \
	X(yaml_document_get_root_node) X(yaml_parser_delete) \
	X(yaml_parser_initialize) X(yaml_parser_load) \
	X(yaml_parser_set_input_string)

/* each member the address of what the library exports under its name */
#define RC_DL_MEMBER(f) __typeof__(f) *f;
struct rc__dl_zip_api { RC_DL_ZIP_FUNCS(RC_DL_MEMBER) };
struct rc__dl_xml_api { RC_DL_XML_FUNCS(RC_DL_MEMBER) };
struct rc__dl_yaml_api { RC_DL_YAML_FUNCS(RC_DL_MEMBER) };
#undef RC_DL_MEMBER

extern struct rc__dl_zip_api rc__dl_zip_api;
extern struct rc__dl_xml_api rc__dl_xml_api;
extern struct rc__dl_yaml_api rc__dl_yaml_api;

int rc__dl_zip(rc_err *err);
int rc__dl_xml(rc_err *err);
int rc__dl_yaml(rc_err *err);

#ifndef RC_IO_DL_C	/* io_dl.c fills the tables under the plain names */
#undef xmlFree
#define zip_close (*rc__dl_zip_api.zip_close)
#define zip_discard (*rc__dl_zip_api.zip_discard)
#define zip_error_fini (*rc__dl_zip_api.zip_error_fini)
#define zip_error_init (*rc__dl_zip_api.zip_error_init)
#define zip_error_strerror (*rc__dl_zip_api.zip_error_strerror)
#define zip_fclose (*rc__dl_zip_api.zip_fclose)
#define zip_file_add (*rc__dl_zip_api.zip_file_add)
#define zip_fopen (*rc__dl_zip_api.zip_fopen)
#define zip_fread (*rc__dl_zip_api.zip_fread)
#define zip_name_locate (*rc__dl_zip_api.zip_name_locate)
#define zip_open_from_source (*rc__dl_zip_api.zip_open_from_source)
#define zip_set_file_compression (*rc__dl_zip_api.zip_set_file_compression)
#define zip_source_buffer (*rc__dl_zip_api.zip_source_buffer)
#define zip_source_buffer_create (*rc__dl_zip_api.zip_source_buffer_create)
#define zip_source_close (*rc__dl_zip_api.zip_source_close)
#define zip_source_error (*rc__dl_zip_api.zip_source_error)
#define zip_source_free (*rc__dl_zip_api.zip_source_free)
#define zip_source_keep (*rc__dl_zip_api.zip_source_keep)
#define zip_source_open (*rc__dl_zip_api.zip_source_open)
#define zip_source_read (*rc__dl_zip_api.zip_source_read)
#define zip_stat (*rc__dl_zip_api.zip_stat)
#define zip_strerror (*rc__dl_zip_api.zip_strerror)
#define xmlAddChild (*rc__dl_xml_api.xmlAddChild)
#define xmlDocDumpFormatMemoryEnc (*rc__dl_xml_api.xmlDocDumpFormatMemoryEnc)
#define xmlDocGetRootElement (*rc__dl_xml_api.xmlDocGetRootElement)
#define xmlDocSetRootElement (*rc__dl_xml_api.xmlDocSetRootElement)
#define xmlFreeDoc (*rc__dl_xml_api.xmlFreeDoc)
#define xmlFreeTextReader (*rc__dl_xml_api.xmlFreeTextReader)
#define xmlGetNsProp (*rc__dl_xml_api.xmlGetNsProp)
#define xmlGetProp (*rc__dl_xml_api.xmlGetProp)
#define xmlNewDoc (*rc__dl_xml_api.xmlNewDoc)
#define xmlNewDocRawNode (*rc__dl_xml_api.xmlNewDocRawNode)
#define xmlNewNode (*rc__dl_xml_api.xmlNewNode)
#define xmlNewNs (*rc__dl_xml_api.xmlNewNs)
#define xmlNodeGetContent (*rc__dl_xml_api.xmlNodeGetContent)
#define xmlReadMemory (*rc__dl_xml_api.xmlReadMemory)
#define xmlReaderForMemory (*rc__dl_xml_api.xmlReaderForMemory)
#define xmlSetNs (*rc__dl_xml_api.xmlSetNs)
#define xmlSetProp (*rc__dl_xml_api.xmlSetProp)
#define xmlTextReaderConstLocalName (*rc__dl_xml_api.xmlTextReaderConstLocalName)
#define xmlTextReaderExpand (*rc__dl_xml_api.xmlTextReaderExpand)
#define xmlTextReaderNext (*rc__dl_xml_api.xmlTextReaderNext)
#define xmlTextReaderNodeType (*rc__dl_xml_api.xmlTextReaderNodeType)
#define xmlTextReaderRead (*rc__dl_xml_api.xmlTextReaderRead)
#define xmlFree (*rc__dl_xml_api.xmlFree)
#define yaml_document_delete (*rc__dl_yaml_api.yaml_document_delete)
#define yaml_document_get_node (*rc__dl_yaml_api.yaml_document_get_node)
#define yaml_document_get_root_node (*rc__dl_yaml_api.yaml_document_get_root_node)
#define yaml_parser_delete (*rc__dl_yaml_api.yaml_parser_delete)
#define yaml_parser_initialize (*rc__dl_yaml_api.yaml_parser_initialize)
#define yaml_parser_load (*rc__dl_yaml_api.yaml_parser_load)
#define yaml_parser_set_input_string (*rc__dl_yaml_api.yaml_parser_set_input_string)
#endif

#endif
