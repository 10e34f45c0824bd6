from http import HTTPStatus
from typing import Any
from urllib.parse import quote

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.get_job_results_format_type_0 import GetJobResultsFormatType0
from ...models.job_results import JobResults
from ...types import UNSET, Response, Unset


def _get_kwargs(
    job_id: str,
    *,
    format_: GetJobResultsFormatType0 | None | Unset = UNSET,
    offset: int | Unset = 0,
    limit: int | None | Unset = UNSET,
) -> dict[str, Any]:

    params: dict[str, Any] = {}

    json_format_: None | str | Unset
    if isinstance(format_, Unset):
        json_format_ = UNSET
    elif isinstance(format_, GetJobResultsFormatType0):
        json_format_ = format_.value
    else:
        json_format_ = format_
    params["format"] = json_format_

    params["offset"] = offset

    json_limit: int | None | Unset
    if isinstance(limit, Unset):
        json_limit = UNSET
    else:
        json_limit = limit
    params["limit"] = json_limit

    params = {k: v for k, v in params.items() if v is not UNSET and v is not None}

    _kwargs: dict[str, Any] = {
        "method": "get",
        "url": "/v1/jobs/{job_id}/results".format(
            job_id=quote(str(job_id), safe=""),
        ),
        "params": params,
    }

    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> ErrorOut | JobResults | None:
    if response.status_code == 200:
        response_200 = JobResults.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 404:
        response_404 = ErrorOut.from_dict(response.json())

        return response_404

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[ErrorOut | JobResults]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
    format_: GetJobResultsFormatType0 | None | Unset = UNSET,
    offset: int | Unset = 0,
    limit: int | None | Unset = UNSET,
) -> Response[ErrorOut | JobResults]:
    """The finished rows: JSON pages, or CSV streamed (?format=csv or Accept: text/csv)

     One row per finished point, by index: `index`, the swept parameters, the analysis's columns and
    `error` (`null`, or `code: message` for a point that failed). While the job runs these are the
    partial results (`complete`: false).

    JSON is paged: `offset` (default 0) and `limit` (default 1000; a larger one is cut to the server's
    `TENSEGRITY_JOBS_RESULTS_MAX_LIMIT`, 10000 by default, and the answer's `limit` says the one
    applied); `done` is the number of rows there are, `next_offset` the offset of the next page (`null`
    on the last one).

    CSV is streamed from the store in batches: every row from `offset` (all of them by default; `limit`
    bounds it, without the JSON maximum). Header = `columns`, lists as JSON text, missing values empty;
    response headers `X-Total-Rows` (rows there are) and, when `limit` leaves rows out, `X-Next-Offset`.

    Args:
        job_id (str):
        format_ (GetJobResultsFormatType0 | None | Unset): json or csv (default: from the Accept
            header, else json)
        offset (int | Unset): rows to skip Default: 0.
        limit (int | None | Unset): most rows: JSON default 1000, cut to
            TENSEGRITY_JOBS_RESULTS_MAX_LIMIT; CSV default all

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | JobResults]
    """

    kwargs = _get_kwargs(
        job_id=job_id,
        format_=format_,
        offset=offset,
        limit=limit,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
    format_: GetJobResultsFormatType0 | None | Unset = UNSET,
    offset: int | Unset = 0,
    limit: int | None | Unset = UNSET,
) -> ErrorOut | JobResults | None:
    """The finished rows: JSON pages, or CSV streamed (?format=csv or Accept: text/csv)

     One row per finished point, by index: `index`, the swept parameters, the analysis's columns and
    `error` (`null`, or `code: message` for a point that failed). While the job runs these are the
    partial results (`complete`: false).

    JSON is paged: `offset` (default 0) and `limit` (default 1000; a larger one is cut to the server's
    `TENSEGRITY_JOBS_RESULTS_MAX_LIMIT`, 10000 by default, and the answer's `limit` says the one
    applied); `done` is the number of rows there are, `next_offset` the offset of the next page (`null`
    on the last one).

    CSV is streamed from the store in batches: every row from `offset` (all of them by default; `limit`
    bounds it, without the JSON maximum). Header = `columns`, lists as JSON text, missing values empty;
    response headers `X-Total-Rows` (rows there are) and, when `limit` leaves rows out, `X-Next-Offset`.

    Args:
        job_id (str):
        format_ (GetJobResultsFormatType0 | None | Unset): json or csv (default: from the Accept
            header, else json)
        offset (int | Unset): rows to skip Default: 0.
        limit (int | None | Unset): most rows: JSON default 1000, cut to
            TENSEGRITY_JOBS_RESULTS_MAX_LIMIT; CSV default all

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | JobResults
    """

    return sync_detailed(
        job_id=job_id,
        client=client,
        format_=format_,
        offset=offset,
        limit=limit,
    ).parsed


async def asyncio_detailed(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
    format_: GetJobResultsFormatType0 | None | Unset = UNSET,
    offset: int | Unset = 0,
    limit: int | None | Unset = UNSET,
) -> Response[ErrorOut | JobResults]:
    """The finished rows: JSON pages, or CSV streamed (?format=csv or Accept: text/csv)

     One row per finished point, by index: `index`, the swept parameters, the analysis's columns and
    `error` (`null`, or `code: message` for a point that failed). While the job runs these are the
    partial results (`complete`: false).

    JSON is paged: `offset` (default 0) and `limit` (default 1000; a larger one is cut to the server's
    `TENSEGRITY_JOBS_RESULTS_MAX_LIMIT`, 10000 by default, and the answer's `limit` says the one
    applied); `done` is the number of rows there are, `next_offset` the offset of the next page (`null`
    on the last one).

    CSV is streamed from the store in batches: every row from `offset` (all of them by default; `limit`
    bounds it, without the JSON maximum). Header = `columns`, lists as JSON text, missing values empty;
    response headers `X-Total-Rows` (rows there are) and, when `limit` leaves rows out, `X-Next-Offset`.

    Args:
        job_id (str):
        format_ (GetJobResultsFormatType0 | None | Unset): json or csv (default: from the Accept
            header, else json)
        offset (int | Unset): rows to skip Default: 0.
        limit (int | None | Unset): most rows: JSON default 1000, cut to
            TENSEGRITY_JOBS_RESULTS_MAX_LIMIT; CSV default all

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | JobResults]
    """

    kwargs = _get_kwargs(
        job_id=job_id,
        format_=format_,
        offset=offset,
        limit=limit,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    job_id: str,
    *,
    client: AuthenticatedClient | Client,
    format_: GetJobResultsFormatType0 | None | Unset = UNSET,
    offset: int | Unset = 0,
    limit: int | None | Unset = UNSET,
) -> ErrorOut | JobResults | None:
    """The finished rows: JSON pages, or CSV streamed (?format=csv or Accept: text/csv)

     One row per finished point, by index: `index`, the swept parameters, the analysis's columns and
    `error` (`null`, or `code: message` for a point that failed). While the job runs these are the
    partial results (`complete`: false).

    JSON is paged: `offset` (default 0) and `limit` (default 1000; a larger one is cut to the server's
    `TENSEGRITY_JOBS_RESULTS_MAX_LIMIT`, 10000 by default, and the answer's `limit` says the one
    applied); `done` is the number of rows there are, `next_offset` the offset of the next page (`null`
    on the last one).

    CSV is streamed from the store in batches: every row from `offset` (all of them by default; `limit`
    bounds it, without the JSON maximum). Header = `columns`, lists as JSON text, missing values empty;
    response headers `X-Total-Rows` (rows there are) and, when `limit` leaves rows out, `X-Next-Offset`.

    Args:
        job_id (str):
        format_ (GetJobResultsFormatType0 | None | Unset): json or csv (default: from the Accept
            header, else json)
        offset (int | Unset): rows to skip Default: 0.
        limit (int | None | Unset): most rows: JSON default 1000, cut to
            TENSEGRITY_JOBS_RESULTS_MAX_LIMIT; CSV default all

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | JobResults
    """

    return (
        await asyncio_detailed(
            job_id=job_id,
            client=client,
            format_=format_,
            offset=offset,
            limit=limit,
        )
    ).parsed
