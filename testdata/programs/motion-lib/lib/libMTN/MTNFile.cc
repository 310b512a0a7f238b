//
// MTNFile.cc
//

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "MTNFile.h"

MTNFile::MTNFile() : buffer(0), header(0), records(0)
{
}

MTNFile::~MTNFile()
{
    Unload();
}

int
MTNFile::Load(const char* path)
{
    Unload();

    FILE* fp = fopen(path, "rb");
    if (fp == NULL) return -1;

    fseek(fp, 0, SEEK_END);
    long size = ftell(fp);
    fseek(fp, 0, SEEK_SET);

    if (size < (long)sizeof(MTNHeader)) {
        fclose(fp);
        return -2;
    }

    buffer = (byte*)malloc(size);
    if (buffer == NULL) {
        fclose(fp);
        return -3;
    }

    if (fread(buffer, 1, size, fp) != (size_t)size) {
        fclose(fp);
        Unload();
        return -4;
    }
    fclose(fp);

    header  = (MTNHeader*)buffer;
    records = (slongword*)(buffer + sizeof(MTNHeader));

    if (header->magic != MTN_MAGIC || header->version != MTN_VERSION) {
        Unload();
        return -5;
    }

    long expected = sizeof(MTNHeader) + GetNumRecordWords() * sizeof(slongword);
    if (size != expected) {
        Unload();
        return -6;
    }
    return 0;
}

void
MTNFile::Unload()
{
    if (buffer != NULL) free(buffer);
    buffer  = 0;
    header  = 0;
    records = 0;
}

longword
MTNFile::GetNumRecordWords() const
{
    return header->numKeyFrames * (header->numJoints + 1);
}

slongword
MTNFile::GetAngle(int keyFrame, int joint) const
{
    return records[keyFrame * (header->numJoints + 1) + joint];
}

slongword
MTNFile::GetSteps(int keyFrame) const
{
    return records[keyFrame * (header->numJoints + 1) + header->numJoints];
}
