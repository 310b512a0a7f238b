//
// Stats.cc : small helpers over arrays of sensor values.
//
// FindFirst uses its loop variable after the loop: gcc 3.3's old
// for-scope rule kept "i" visible until the end of the function.
//

int
FindFirst(const int* values, int num, int key)
{
    for (int i = 0; i < num; i++) {
        if (values[i] == key) break;
    }
    return (i < num) ? i : -1;
}

int
CountAbove(const int* values, int num, int limit)
{
    int n = 0;
    for (int k = 0; k < num; k++) if (values[k] > limit) n++;
    return n;
}
